#include <deal.II/base/timer.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/augmented_lagrangian_solver.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>

namespace hrcontact
{
  using namespace dealii;

  void
  AugmentedLagrangianSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Augmented Lagrangian");
    prm.declare_entry(
      "Initial penalty",
      "1e4",
      Patterns::Anything(),
      "Initial compliance alpha_0 of every unilateral constraint (an "
      "expression of the constants): with Initial penalty scaling = nodal "
      "compliance, a factor times the nodal compliance of the mesh and "
      "material; with absolute, a length per force. Small against the nodal "
      "compliance ties released nodes to their trial position and slows "
      "convergence (the paper's Fig. 14); large makes the iteration behave "
      "like an active-set method, until the released springs no longer hold "
      "the body.");
    prm.declare_entry(
      "Initial penalty scaling",
      "nodal compliance",
      Patterns::Selection("nodal compliance|absolute"),
      "nodal compliance: alpha_0 = Initial penalty x c_h, with c_h = (1 - "
      "nu^2)/E in plane strain, 1/E in plane stress (length per force per unit "
      "thickness) and 1/(E h) in 3D, h the mean cell size (volume / cells)^(1/3): "
      "the compliance of a boundary node up to a factor of order one, so the "
      "same factor works in any units and on any mesh. absolute: alpha_0 = "
      "Initial penalty as given (the paper's 0.001).");
    prm.declare_entry("Penalty growth factor",
                      "10",
                      Patterns::Double(1),
                      "rho of eq. 49: alpha <- rho alpha when ||pbar|| did not "
                      "fall enough.");
    prm.declare_entry("Penalty update threshold",
                      "0.25",
                      Patterns::Double(0, 1),
                      "delta of eq. 49: alpha grows when ||pbar|| > delta "
                      "||pbar_previous||.");
    prm.declare_entry("Penalty update",
                      "global",
                      Patterns::Selection("global|per constraint"),
                      "global: one alpha for all constraints, updated from "
                      "the norms; per constraint: alpha_i updated from "
                      "|pbar_i|.");
    prm.declare_entry("Minimum inner tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "eps_min of Step 2: each inner Newton solve reduces the "
                      "gradient norm of eq. 46 by the factor eps_k at least "
                      "(or stops earlier when a full step keeps the released "
                      "set: then it is exact).");
    prm.declare_entry("Maximum inner tolerance",
                      "1e-2",
                      Patterns::Double(0),
                      "eps_max of Step 2 (same units as eps_min).");
    prm.declare_entry("Absolute tolerance",
                      "0",
                      Patterns::Double(0),
                      "Stop (Step 6) when ||pbar|| is below this force "
                      "(0: use the relative tolerance only).");
    prm.declare_entry(
      "Relative tolerance",
      "1e-10",
      Patterns::Double(0),
      "Stop (Step 6) when ||pbar|| is below this times the load "
      "scale (the largest of the applied load and the trial "
      "reactions; under Nested iteration the coarsest level's trial "
      "reactions, carried up at the factor per level that the second "
      "level measures with a trial solve of its own).");
    prm.declare_entry("Maximum multiplier updates",
                      "100",
                      Patterns::Integer(1),
                      "Iteration limit: reaching it is an error (exit code 3), "
                      "but all result files are written with converged = "
                      "false.");
    prm.declare_entry(
      "Maximum penalty growth",
      "1e16",
      Patterns::Double(1),
      "alpha may grow (eq. 49) up to this factor times Initial penalty. "
      "Needing more means the iteration is not converging at any penalty the "
      "mesh can carry (typically Initial penalty far too large against the "
      "nodal compliance): the run stops with an error naming the cause, and "
      "writes its results with converged = false.");
    prm.declare_entry(
      "Regularisation",
      "consistent augmented Lagrangian",
      Patterns::Selection("consistent augmented Lagrangian|Macaulay augmented "
                          "Lagrangian|pure penalty|displacement augmented "
                          "Lagrangian"),
      "consistent augmented Lagrangian: the paper's eq. 28, pbar = max(p, "
      "mu/alpha), with multiplier updates (eq. 48) and penalty updates (eq. "
      "49). Macaulay augmented Lagrangian: eq. 27 on the same constraint, pbar "
      "= max(p, 0): a row is released only once it pulls, and a pressed row "
      "is held whatever its multiplier (the Hessian jumps at p = 0). pure "
      "penalty: mu stays 0 and alpha stays Initial penalty; the quadratic piece "
      "is solved exactly once. A released constraint is then a spring of "
      "compliance alpha anchored at the gap, so it carries a tension of about "
      "(opening) / alpha: an error that shrinks only as alpha grows (and the "
      "solves degrade). displacement augmented Lagrangian: eq. 29, what a "
      "displacement code does: multiplier gamma (the reaction) and a stiffness "
      "beta on the penetration w_n - g, a row in contact while gamma + beta (w_n "
      "- g) > 0; Initial penalty is then the stiffness beta_0 (with nodal "
      "compliance scaling: the factor divides c_h). It needs the condensed "
      "path; ||pbar|| in the logs is then the change of the reactions.");
    prm.declare_entry(
      "Iteration scheme",
      "classical",
      Patterns::Selection("classical|diagonal"),
      "Section 4.4. classical: Newton steps until the inner tolerance eps_k, "
      "then one multiplier update. diagonal: one Newton step, then one "
      "multiplier update (for the stress variants the update of a row uses "
      "the piece that step solved). The pure penalty ignores this entry.");
    prm.declare_entry("Maximum Newton steps",
                      "50",
                      Patterns::Integer(1),
                      "Newton steps per multiplier update at most.");
    prm.declare_entry(
      "Update carried multipliers with each Newton step",
      "true",
      Patterns::Bool(),
      "After a carried start (a coarser level's state under Nested "
      "iteration, or the last material step's), the classical scheme's "
      "Newton steps that switch rows also give every row that keeps its "
      "branch the multiplier update of eq. 48 from the last solve, instead "
      "of waiting for the first update. The carried multipliers are the "
      "coarser level's; corrected this way they no longer need an update "
      "solve of their own once the set has settled (Hertz refinement 7: 3 "
      "fine solves instead of 4, doc/benchmarks.md). The convergence test "
      "is the same either way. false: the carried multipliers stay fixed "
      "until the first update.");
    prm.leave_subsection();
  }

  void
  AugmentedLagrangianSolver::parse_parameters(ParameterHandler &prm,
                                              const Constants  &constants)
  {
    prm.enter_subsection("Augmented Lagrangian");
    initial_penalty =
      evaluate_constant_expression(prm.get("Initial penalty"),
                                   constants,
                                   "Augmented Lagrangian/Initial penalty");
    scale_by_compliance =
      (prm.get("Initial penalty scaling") == "nodal compliance");
    if (!(initial_penalty > 0))
      throw InputError(
        "Augmented Lagrangian/Initial penalty must be positive.");
    rho                = prm.get_double("Penalty growth factor");
    delta              = prm.get_double("Penalty update threshold");
    per_constraint     = (prm.get("Penalty update") == "per constraint");
    eps_min            = prm.get_double("Minimum inner tolerance");
    eps_max            = prm.get_double("Maximum inner tolerance");
    absolute_tolerance = prm.get_double("Absolute tolerance");
    relative_tolerance = prm.get_double("Relative tolerance");
    max_updates        = prm.get_integer("Maximum multiplier updates");
    max_newton_steps   = prm.get_integer("Maximum Newton steps");
    update_carried_multipliers =
      prm.get_bool("Update carried multipliers with each Newton step");
    {
      const std::string r = prm.get("Regularisation");
      regularisation = (r == "pure penalty") ? Regularisation::pure_penalty :
                       (r == "Macaulay augmented Lagrangian") ?
                                               Regularisation::macaulay :
                       (r == "displacement augmented Lagrangian") ?
                                               Regularisation::displacement :
                                               Regularisation::consistent;
    }
    // The pure penalty has no multiplier updates to interleave.
    diagonal = (prm.get("Iteration scheme") == "diagonal") &&
               regularisation != Regularisation::pure_penalty;
    // alpha_0 before the mesh is known: c_h = 1 (set_nodal_compliance sets it).
    set_nodal_compliance(1.);
    max_penalty_growth = prm.get_double("Maximum penalty growth");
    prm.leave_subsection();
    if (eps_min > eps_max)
      throw InputError("Augmented Lagrangian: Minimum inner tolerance exceeds "
                       "Maximum inner tolerance.");
  }

  void
  AugmentedLagrangianSolver::set_nodal_compliance(const double c)
  {
    nodal_compliance = c;
    // The displacement AL reads Initial penalty as a stiffness beta_0 and
    // keeps alpha_0 = 1 / beta_0.
    if (regularisation == Regularisation::displacement)
      initial_alpha =
        scale_by_compliance ? c / initial_penalty : 1. / initial_penalty;
    else
      initial_alpha =
        scale_by_compliance ? initial_penalty * c : initial_penalty;
  }

  const ConstraintLaw &
  AugmentedLagrangianSolver::law_of(const EquilibriumRow &row) const
  {
    static const BilateralConstraint       bilateral;
    static const UnilateralContact         consistent;
    static const MacaulayUnilateralContact macaulay;
    if (row.law)
      return *row.law;
    if (!row.unilateral)
      return bilateral;
    return (regularisation == Regularisation::macaulay) ? macaulay : consistent;
  }

  namespace
  {
    /** The entries of v at the given rows: a process's part of a state. */
    template <typename T>
    std::vector<T>
    part_of(const std::vector<T> &v, const std::vector<unsigned int> &rows)
    {
      std::vector<T> part;
      part.reserve(rows.size());
      for (const unsigned int i : rows)
        part.push_back(v[i]);
      return part;
    }

    /**
     * The sets (of branches, of rows in contact) an iteration has solved,
     * each process keeping the part of its own rows: a set was solved
     * before when every process finds its part at the same earlier step.
     */
    template <typename Key>
    class SolvedSets
    {
    public:
      explicit SolvedSets(const ContactRowPartition &ownership)
        : ownership(ownership)
      {}
      /** Record key; false if it was solved before. */
      bool
      insert(const Key &key)
      {
        if (!keys.empty())
          {
            std::vector<bool> same(keys.size());
            for (unsigned int j = 0; j < keys.size(); ++j)
              same[j] = (keys[j] == key);
            same = ownership.all(same);
            if (std::find(same.begin(), same.end(), true) != same.end())
              return false;
          }
        keys.push_back(key);
        return true;
      }
      void
      clear()
      {
        keys.clear();
      }

    private:
      const ContactRowPartition &ownership;
      std::vector<Key>           keys;
    };
  } // namespace

  void
  AugmentedLagrangianSolver::record(const unsigned int k,
                                    const unsigned int newton_steps,
                                    const double       eps_k,
                                    const double       norm,
                                    const unsigned int changes,
                                    const double       seconds,
                                    std::ostream      &log)
  {
    p_history.push_back(p);
    mu_history.push_back(opening);
    alpha_history.push_back(alpha);
    released_history.push_back(released);

    AugmentedLagrangianStep step;
    step.k            = k;
    step.newton_steps = newton_steps;
    double alpha_min  = std::numeric_limits<double>::infinity();
    double alpha_max  = -alpha_min;
    for (const unsigned int i : ownership->owned())
      {
        alpha_min = std::min(alpha_min, alpha[i]);
        alpha_max = std::max(alpha_max, alpha[i]);
      }
    step.alpha_min      = ownership->min(alpha_min);
    step.alpha_max      = ownership->max(alpha_max);
    step.eps_k          = eps_k;
    step.norm_pbar      = norm;
    step.active_changes = changes;
    step.seconds        = seconds;
    history.push_back(step);
    final_norm_pbar = norm;
    log << "    update " << std::setw(3) << k << ": Newton steps "
        << std::setw(2) << newton_steps << ", ||pbar|| " << std::scientific
        << std::setprecision(3) << norm << ", alpha [" << step.alpha_min << ", "
        << step.alpha_max << "], eps " << eps_k << std::defaultfloat
        << ", status changes " << changes << std::endl;
  }

  bool
  AugmentedLagrangianSolver::update_penalty(
    std::vector<double>       &penalty,
    const std::vector<double> &r,
    const std::vector<double> &r_previous,
    const double               norm,
    const double               norm_previous,
    const double               initial)
  {
    const double cap    = max_penalty_growth * initial;
    bool         capped = false;
    if (per_constraint)
      {
        for (const unsigned int i : ownership->relevant())
          if (std::abs(r[i]) > delta * std::abs(r_previous[i]))
            {
              capped |= (rho * penalty[i] > cap);
              penalty[i] *= rho;
            }
      }
    else if (norm > delta * norm_previous)
      for (const unsigned int i : ownership->relevant())
        {
          capped |= (rho * penalty[i] > cap);
          penalty[i] *= rho;
        }
    capped = !ownership->all(!capped);
    if (capped)
      {
        for (const unsigned int i : ownership->relevant())
          penalty[i] = std::min(penalty[i], cap);
        diverged = true;
      }
    return !capped;
  }

  double
  AugmentedLagrangianSolver::inner_tolerance(const double norm,
                                             double      &eps_previous) const
  {
    // Step 2, made unit free with the load scale.
    const double relative = norm / force_scale;
    const double eps_k =
      std::max(eps_min, std::min({eps_max, eps_previous, relative * relative}));
    eps_previous = eps_k;
    return eps_k;
  }

  void
  AugmentedLagrangianSolver::start_from(const ContactStart &s)
  {
    if (regularisation == Regularisation::pure_penalty ||
        regularisation == Regularisation::displacement)
      throw InputError("Augmented Lagrangian: the pure penalty and the "
                       "displacement augmented Lagrangian cannot start from a "
                       "carried state (nested iteration).");
    start     = s;
    has_start = true;
  }

  bool
  AugmentedLagrangianSolver::solve(const EquilibriumSystem &system,
                                   NewtonStepPath          &path,
                                   const double             load_scale,
                                   std::ostream            &log)
  {
    relinearisation = nullptr;
    iterate(system, path, load_scale, log);
    gather_state();
    set_outcome();
    return converged;
  }

  bool
  AugmentedLagrangianSolver::solve(const EquilibriumSystem &system,
                                   NewtonStepPath          &path,
                                   const double             load_scale,
                                   RowRelinearisation      &relinearise,
                                   std::ostream            &log)
  {
    relinearisation = &relinearise;
    iterate(system, path, load_scale, log);
    relinearisation = nullptr;
    gather_state();
    set_outcome();
    return converged;
  }

  void
  AugmentedLagrangianSolver::set_outcome()
  {
    // One outcome, in the order in which the causes explain each other.
    outcome = floating         ? SolveOutcome::floating :
              roundoff_limited ? SolveOutcome::roundoff_limited :
              periodic         ? SolveOutcome::periodic :
              cycled           ? SolveOutcome::inner_cycle :
              diverged         ? SolveOutcome::diverged :
              converged        ? SolveOutcome::converged :
                                 SolveOutcome::iteration_limit;
  }

  void
  AugmentedLagrangianSolver::gather_state()
  {
    if (!ownership || !ownership->distributed())
      return;
    // Once per solve: the complete state for the tables, the nested
    // transfer and the next solve's start, each row from its owner.
    for (auto *v : {&p, &mu, &alpha, &opening})
      ownership->gather(*v);
    ownership->gather(released);
    std::vector<double> spring(pieces.size()), offset(pieces.size()),
      compliance(pieces.size()), branch(pieces.size());
    for (unsigned int i = 0; i < pieces.size(); ++i)
      {
        spring[i]     = pieces[i].spring;
        offset[i]     = pieces[i].offset;
        compliance[i] = pieces[i].compliance;
        branch[i]     = pieces[i].branch;
      }
    for (auto *v : {&spring, &offset, &compliance, &branch})
      ownership->gather(*v);
    for (unsigned int i = 0; i < pieces.size(); ++i)
      {
        pieces[i].spring     = (spring[i] != 0);
        pieces[i].offset     = offset[i];
        pieces[i].compliance = compliance[i];
        pieces[i].branch     = static_cast<unsigned int>(branch[i]);
      }
    for (auto *history_of : {&p_history, &mu_history, &alpha_history})
      for (auto &v : *history_of)
        ownership->gather(v);
    for (auto &v : released_history)
      ownership->gather(v);
  }

  bool
  AugmentedLagrangianSolver::found_floating_body(
    const std::function<bool(unsigned int)> &is_free,
    const unsigned int                       update)
  {
    // Each process asks about the rows it owns.
    for (const BodyHeldByContact &body : held_only_by_contact)
      if (ownership->all(std::all_of(
            body.rows.begin(), body.rows.end(), [&](const unsigned int i) {
              return !ownership->is_owned(i) || is_free(i);
            })))
        {
          floating        = true;
          floating_update = update;
          floating_body   = body.name;
          return true;
        }
    return false;
  }

  std::string
  AugmentedLagrangianSolver::outcome_message(
    unsigned int free_rigid_motions) const
  {
    const std::string mechanism_hint =
      free_rigid_motions == 0 ?
        std::string() :
        " Note: only the contacts hold this body along " +
          std::to_string(free_rigid_motions) +
          " rigid-body motion(s); if the loads pull it off its obstacles, no "
          "equilibrium exists (a mechanism).";
    std::ostringstream s;
    switch (outcome)
      {
        case SolveOutcome::converged:
          return "";
        case SolveOutcome::floating:
          // In a scene of several bodies: the floating one's motions.
          for (const auto &body : held_only_by_contact)
            if (!floating_body.empty() && body.name == floating_body)
              free_rigid_motions = body.free_motions;
          return "every contact constraint" +
                 (floating_body.empty() ? std::string() :
                                          " of " + floating_body) +
                 " released at multiplier update " +
                 std::to_string(floating_update) +
                 ", and nothing else holds the body: the supports leave " +
                 std::to_string(free_rigid_motions) +
                 " rigid-body motion(s) free, and the loads pull the body off "
                 "its obstacles along them (a mechanism: no equilibrium "
                 "exists). Check the direction of the loads, the obstacles' "
                 "normals and the supports. Results were written with "
                 "converged = false.";
        case SolveOutcome::roundoff_limited:
          s << "the displacement augmented Lagrangian reached its round-off "
               "floor at multiplier update "
            << history.size() << ": the change of the reactions, "
            << final_norm_pbar
            << ", has reached the noise floor that the rounding of the "
               "displacements and the linear solver's tolerance leave at this "
               "stiffness (about "
            << roundoff_floor << "), above the tolerance " << tolerance_used
            << ". Loosen Augmented Lagrangian/Relative tolerance, reduce "
               "Initial penalty, or tighten Linear solver/Tolerance. Results "
               "were written with converged = false.";
          return s.str();
        case SolveOutcome::periodic:
          return "the diagonal scheme cycles: multiplier update " +
                 std::to_string(history.size()) +
                 " reproduced an earlier update (the same branches, penalties "
                 "and multipliers), so the iteration is periodic and would "
                 "never converge. Take Augmented Lagrangian/Iteration scheme = "
                 "classical, or another Initial penalty." +
                 mechanism_hint +
                 " Results were written with converged = false.";
        case SolveOutcome::inner_cycle:
          return "the inner Newton iteration of multiplier update " +
                 std::to_string(history.size() + 1) +
                 " cycles: it came back to a released set it had already "
                 "solved, so it would never reach its tolerance. " +
                 std::string(
                   regularisation == Regularisation::macaulay ?
                     "The Macaulay bracket (p)_+ has a kink at p = 0 wherever "
                     "mu is not 0, so its pieces do not join with a continuous "
                     "slope. Use the consistent augmented Lagrangian, or "
                     "Iteration scheme = diagonal." :
                     cycle_cause()) +
                 mechanism_hint +
                 " Results were written with converged = false.";
        case SolveOutcome::diverged:
          s << "the augmented Lagrangian iteration stopped at multiplier update "
            << history.size()
            << " without converging: ||pbar|| = " << final_norm_pbar
            << " either exceeds a million times the load scale or would need "
               "alpha beyond Maximum penalty growth x Initial penalty (alpha "
               "is "
            << alpha.front()
            << "). The usual cause is an Initial penalty far from the nodal "
               "compliance of the mesh: far larger, the released springs no "
               "longer hold the body and the solves lose their digits; far "
               "smaller, alpha cannot grow enough. Adjust Augmented "
               "Lagrangian/Initial penalty."
            << mechanism_hint
            << " Results were written with converged = false.";
          return s.str();
        case SolveOutcome::iteration_limit:
          s << "the augmented Lagrangian iteration did not converge in "
            << history.size()
            << " multiplier updates (Augmented Lagrangian/Maximum multiplier "
               "updates): ||pbar|| = "
            << final_norm_pbar << " > tolerance " << tolerance_used
            << ". Results were written with "
            << "converged = false.";
          return s.str();
      }
    return "";
  }

  std::string
  AugmentedLagrangianSolver::cycle_cause() const
  {
    std::ostringstream s;
    s << "The pieces join smoothly, so the solves have lost their digits: ";
    if (cycle_linear_tolerance > 0)
      s << "CG was tightened to " << cycle_linear_tolerance
        << " of the right-hand side and still cycles, so the rounding of the "
           "solves themselves is the limit. Take Linear solver/Solver = "
           "direct, or reduce Augmented Lagrangian/Initial penalty if it is "
           "far above the nodal compliance (released springs that no longer "
           "hold the body).";
    else
      s << "the usual cause is an Initial penalty far larger than the nodal "
           "compliance of the mesh (released springs that no longer hold the "
           "body). Reduce Augmented Lagrangian/Initial penalty.";
    return s.str();
  }

  bool
  AugmentedLagrangianSolver::iterate(const EquilibriumSystem &system,
                                     NewtonStepPath          &path,
                                     const double             load_scale,
                                     std::ostream            &log)
  {
    const unsigned int nq = system.contact_rows.size();
    // The rows this process owns and sees: every loop below runs over the
    // rows it sees, every norm, count and decision is a reduction over the
    // owned ones (ContactRowPartition).
    ownership = &path.row_partition();
    AssertThrow(ownership->n_rows() == nq, ExcInternalError());
    const std::vector<unsigned int> &rows_here = ownership->relevant();
    rows_owned                                 = ownership->owned().size();
    rows_seen                                  = rows_here.size();
    std::vector<bool> unilateral(nq);
    law.assign(nq, nullptr);
    for (unsigned int i = 0; i < nq; ++i)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        unilateral[i]             = row.unilateral && !row.law;
        law[i]                    = &law_of(row);
      }

    Timer timer;
    alpha_0 = initial_alpha;
    mu.assign(nq, 0.);
    alpha.assign(nq, initial_alpha);
    released.assign(nq, false);
    opening.assign(nq, 0.);
    history.clear();
    p_history.clear();
    mu_history.clear();
    alpha_history.clear();
    released_history.clear();
    total_newton_steps = 0;
    converged          = false;
    diverged           = false;
    cycled             = false;
    periodic           = false;
    floating           = false;
    floating_body.clear();
    roundoff_limited       = false;
    roundoff_floor         = 0;
    cycle_linear_tolerance = 0;

    // Step 0: trial solution, every constraint bilateral with w_n = g; or
    // the carried state of a coarser level (start_from): its multipliers and
    // compliances, and the pieces its reactions select.
    pieces.assign(nq, ContactPiece());
    for (unsigned int i = 0; i < nq; ++i)
      pieces[i] = law[i]->trial_piece();
    const bool started = has_start;
    has_start          = false;
    scale_per_level    = started ? start.scale_per_level : 0.;
    // The first carried level of nested iteration solves its own trial once
    // (every row held, as Step 0 without a start) for the force scale of
    // its tolerance, and measures how that scale shrinks per level; the
    // finer levels carry it on. Without this they would stop at a tighter
    // ||pbar|| than their own trial would set (Hertz refinement 9: 0.00159
    // instead of about 0.0035), near the solves' round-off (about 7e-4).
    double measured_scale = 0;
    if (started && start.measure_trial_scale)
      {
        path.solve(pieces, p);
        measured_scale = std::abs(load_scale);
        for (const unsigned int i : ownership->owned())
          measured_scale = std::max(measured_scale, std::abs(p[i]));
        measured_scale = ownership->max(measured_scale);
        if (start.tolerance_scale > 0)
          scale_per_level =
            std::min(1.,
                     std::max(start.smallest_scale_per_level,
                              measured_scale / start.tolerance_scale));
      }
    if (started)
      {
        AssertThrow(start.fits(system),
                    ExcMessage("the carried contact state does not fit the "
                               "rows of this system"));
        for (const unsigned int i : rows_here)
          if (law[i]->has_multiplier())
            {
              mu[i]     = start.mu[i];
              alpha[i]  = (start.alpha[i] > 0) ? start.alpha[i] : initial_alpha;
              pieces[i] = law[i]->piece(start.p[i], mu[i], alpha[i]);
            }
      }
    path.solve(pieces, p);

    double scale = std::abs(load_scale);
    for (const unsigned int i : ownership->owned())
      scale = std::max(scale, std::abs(p[i]));
    scale = ownership->max(scale);
    if (measured_scale > 0)
      scale = std::max(scale, measured_scale);
    else if (started)
      scale = std::max(scale, start.tolerance_scale);
    tolerance_scale = scale;
    tolerance_used  = std::max(absolute_tolerance, relative_tolerance * scale);
    force_scale     = std::max(scale, 1e-300);

    const bool pure_penalty = (regularisation == Regularisation::pure_penalty);
    // Three digits on this line, whatever the stream held before.
    const std::streamsize precision = log.precision(3);
    // Under MPI: how the rows are shared (reductions on every process).
    std::string shares;
    if (ownership->distributed())
      {
        const double owned = rows_owned, seen = rows_seen;
        shares = " (each process owns " +
                 std::to_string(unsigned(ownership->min(owned))) + " to " +
                 std::to_string(unsigned(ownership->max(owned))) +
                 " and updates at most " +
                 std::to_string(unsigned(ownership->max(seen))) + ")";
      }
    log << "  augmented Lagrangian ("
        << (regularisation == Regularisation::consistent ? "consistent" :
            regularisation == Regularisation::macaulay   ? "Macaulay" :
            pure_penalty                                 ? "pure penalty" :
                                                           "displacement")
        << ", " << (diagonal ? "diagonal" : "classical") << "): " << nq
        << " contact constraints" << shares << ", initial "
        << (regularisation == Regularisation::displacement ? "stiffness beta " :
                                                             "alpha ")
        << (regularisation == Regularisation::displacement ? 1 / initial_alpha :
                                                             initial_alpha);
    if (scale_by_compliance)
      log << " (" << initial_penalty
          << (regularisation == Regularisation::displacement ? " / " : " x ")
          << "nodal compliance " << nodal_compliance << ")";
    log << ", tolerance " << tolerance_used;
    if (measured_scale > 0)
      log << " (this level's trial reactions, " << scale_per_level
          << " of the coarser level's)";
    else if (started && start.scale_per_level > 0)
      log << " (the trial reactions carried at " << start.scale_per_level
          << " per level)";
    if (started)
      log << ", started from " << start.origin;
    log << std::endl;
    log.precision(precision);

    if (regularisation == Regularisation::displacement)
      {
        for (unsigned int i = 0; i < nq; ++i)
          if (!unilateral[i] && law[i]->has_multiplier())
            throw InputError(
              "Augmented Lagrangian/Regularisation = displacement augmented "
              "Lagrangian is implemented for unilateral contact only; " +
              system.describe_row(system.contact_rows[i]) + " has the law '" +
              law[i]->name() + "'. Take the consistent augmented Lagrangian.");
        return solve_displacement(system, unilateral, path, timer, log);
      }

    // The piece each row had in the last Newton step, and the value of its
    // relation w - g there: the contact force term that solve balanced.
    std::vector<ContactPiece> solved = pieces;
    std::vector<double>       balanced(nq, 0.);
    for (const unsigned int i : rows_here)
      balanced[i] = solved[i].relation(p[i]);

    std::vector<double> pbar(nq, 0.), pbar_previous(nq, 0.);
    double              norm_previous    = std::numeric_limits<double>::max();
    double              eps_previous     = eps_max;
    double              eps_k            = eps_max;
    unsigned int        newton_steps     = 0;
    bool                last_inner_exact = false;
    bool                geometry_changed = false;
    // The multipliers and compliances of the last solve, kept across an
    // update for the first Newton step after it.
    std::vector<double> mu_solved, alpha_solved;
    bool                updated = false;
    std::vector<std::tuple<std::vector<unsigned int>,
                           std::vector<double>,
                           std::vector<double>>>
      visited;
    // Inexact (CG) solves leave noise in p = Q s - q; three symptoms of it
    // tighten CG's tolerance for the remaining solves (tighten_linear_solver)
    // instead of letting the iteration fail: an inner cycle, an inner
    // iteration at its step limit, and ||pbar|| doubling while no row changed
    // its branch.
    const auto tighten = [&](const std::string &symptom) {
      if (!path.tighten_linear_solver())
        return false;
      log << "    " << symptom << ": CG tolerance tightened to "
          << path.statistics.tolerance << std::endl;
      return true;
    };

    for (unsigned int k = 1;; ++k)
      {
        // A carried start (start_from) begins with Newton steps on its own
        // multipliers and compliances: its first solve is not a trial whose
        // reactions could update the multipliers.
        updated = !(started && k == 1);
        if (updated)
          {
            mu_solved    = mu;
            alpha_solved = alpha;
            // pbar with the multipliers and compliances the solve used.
            for (const unsigned int i : rows_here)
              pbar[i] = law[i]->has_multiplier() ?
                          law[i]->residual(p[i], mu[i], alpha[i]) :
                          0.;
            const double norm = ownership->norm(pbar);

            unsigned int changes = 0;
            for (const unsigned int i : rows_here)
              {
                const ContactPiece current =
                  law[i]->piece(p[i], mu[i], alpha[i]);
                changes += (current.branch != pieces[i].branch &&
                            ownership->is_owned(i));
                pieces[i]   = current;
                released[i] = law[i]->is_free(current.branch);
              }
            changes = ownership->sum(changes);

            // Step 4: multiplier update (eq. 48), mu <- mu - alpha pbar =
            // dL/dp; afterwards mu = w_n - g. The pure penalty keeps mu = 0.
            // The diagonal scheme updates with the piece its single Newton step
            // solved (ConstraintLaw::multiplier_after_step): a row held there
            // (at w_n = g + offset) takes that offset,
            // since p of a held row says nothing yet about how far it moves:
            // updating mu by its reaction would guess a displacement that the
            // next step undoes, and the set then cycles (measured on lift-off).
            if (!pure_penalty)
              for (const unsigned int i : rows_here)
                if (law[i]->has_multiplier())
                  mu[i] = diagonal ? law[i]->multiplier_after_step(solved[i],
                                                                   p[i],
                                                                   mu[i],
                                                                   alpha[i]) :
                                     mu[i] - alpha[i] * pbar[i];
            for (const unsigned int i : rows_here)
              // w_n - g: the updated multiplier for a consistent law; released
              // rows of the pure penalty are springs anchored at the gap (mu =
              // 0), so they open by -alpha p.
              opening[i] = pure_penalty ?
                             pieces[i].relation(p[i]) :
                             law[i]->opening(pieces[i], p[i], mu[i]);

            record(history.size() + 1,
                   newton_steps,
                   eps_k,
                   norm,
                   changes,
                   timer.wall_time(),
                   log);
            // The number of this update (k, or k - 1 after a carried start).
            const unsigned int update = history.size();

            // Step 6: convergence test. The pure penalty is done once the
            // inner solve has reached its exact piece (its own answer, with the
            // tension of the released springs as its error). The diagonal
            // scheme also needs the piece at p to be the one its step solved:
            // else p satisfies another relation, and a small pbar (a stop held
            // at the estimate mu) says nothing about w.
            bool same_pieces = true;
            for (const unsigned int i : rows_here)
              same_pieces &= (pieces[i].branch == solved[i].branch);
            same_pieces = ownership->all(same_pieces);
            if (pure_penalty ?
                  (update > 1 && last_inner_exact) :
                  (norm < tolerance_used && (!diagonal || same_pieces) &&
                   !geometry_changed))
              {
                converged = true;
                break;
              }
            if (update >= max_updates)
              break;
            // The diagonal scheme is a fixed-point map of (mu, alpha): an
            // update that reproduces the multipliers, penalties and branches of
            // an earlier one (to round-off) means it runs in a cycle (measured:
            // a period of 6 on the bridge stops at alpha_0 = 1e4 c_h).
            if (diagonal)
              {
                // Each process compares the rows it sees; an earlier update
                // matches when it matches on every process.
                std::vector<unsigned int> branches;
                double                    mu_scale = 0;
                for (const unsigned int i : rows_here)
                  {
                    branches.push_back(pieces[i].branch);
                    mu_scale = std::max(mu_scale, std::abs(mu[i]));
                  }
                mu_scale                         = ownership->max(mu_scale);
                const std::vector<double> a_here = part_of(alpha, rows_here);
                const std::vector<double> m_here = part_of(mu, rows_here);
                std::vector<bool>         same(visited.size());
                std::vector<double>       difference(visited.size(), 0.);
                for (unsigned int j = 0; j < visited.size(); ++j)
                  {
                    const auto &[b, a, m] = visited[j];
                    same[j]               = (b == branches && a == a_here);
                    for (unsigned int r = 0; r < m.size(); ++r)
                      difference[j] =
                        std::max(difference[j], std::abs(m[r] - m_here[r]));
                  }
                if (!visited.empty())
                  {
                    same = ownership->all(same);
                    for (unsigned int j = 0; j < visited.size(); ++j)
                      {
                        const double largest = ownership->max(difference[j]);
                        periodic |= same[j] && largest <= 1e-12 * mu_scale;
                      }
                  }
                if (periodic)
                  {
                    cycled = true;
                    break;
                  }
                visited.emplace_back(branches, a_here, m_here);
              }
            // Floating: every row with a multiplier on its free branch and none
            // holding (a released row of the consistent AL may still carry
            // compression).
            if (found_floating_body(
                  [&](const unsigned int i) {
                    return (!law[i]->has_multiplier() || released[i]) &&
                           !law[i]->holds(p[i]);
                  },
                  update))
              break;
            // A released spring far softer than the mesh (alpha much larger
            // than the nodal compliance) leaves the body all but unsupported:
            // the solves lose every digit and ||pbar|| explodes. Stop, do not
            // iterate on garbage.
            if (!std::isfinite(norm) || norm > 1e6 * force_scale)
              {
                diverged = true;
                break;
              }

            // Step 5: penalty update (eq. 49), within the allowed growth.
            // The diagonal scheme holds the penalty while the released set
            // still changes: ||pbar|| then jumps with the set, not with a slow
            // multiplier iteration.
            // With no branch changed, the multipliers of a classical update
            // converge, if slowly (||pbar|| may stall at a small alpha: 3D
            // block); a doubling is noise of the solves: tighten CG.
            if (update > 1 && !diagonal && !pure_penalty && changes == 0 &&
                norm > 2 * norm_previous)
              tighten("||pbar|| doubled at update " + std::to_string(update) +
                      " with no status change");
            if (update > 1 && !pure_penalty && !(diagonal && changes > 0) &&
                !update_penalty(alpha,
                                pbar,
                                pbar_previous,
                                norm,
                                norm_previous,
                                initial_alpha))
              break;
            norm_previous = norm;
            pbar_previous = pbar;

            eps_k = pure_penalty ? 0. : // solve the piece exactly
                                   inner_tolerance(norm, eps_previous);
            geometry_changed =
              relinearisation && relinearisation->relinearise(path, opening);
          }

        // Step 3: Newton steps until the gradient, in contact coordinates
        // e = (w - g of the piece at p) - balanced, falls by eps_k (the
        // diagonal scheme: one step). A step that keeps every branch gives
        // e = 0 exactly: the piece is quadratic.
        newton_steps                                       = 0;
        unsigned int                          step_limit   = max_newton_steps;
        double                                initial_norm = 0;
        SolvedSets<std::vector<unsigned int>> solved_sets(*ownership);
        for (;;)
          {
            std::vector<ContactPiece> active(nq);
            std::vector<unsigned int> branches(nq);
            std::vector<double>       e(nq);
            // The first step after a classical update reads a row that the
            // last step solved as a spring with the multipliers that solve
            // used, and re-anchors it at the new ones. Read off the new
            // multipliers, the old p counts the spring's tension twice (p >
            // mu/alpha - p): the rows at the edge of a contact zone switched
            // to held and back, two solves per update (3D block at 807k dofs:
            // 3 Newton steps where 1 suffices). Not where the update grew the
            // compliance: every spring is then softer, and on Hertz's
            // coarsest level the kept springs alone held the body at alpha =
            // 2.3e7 c_h, which MUMPS finds singular. Held rows are read with
            // the new multipliers (the update resets their mu to 0: nothing
            // is counted twice).
            const bool after_update = newton_steps == 0 && updated &&
                                      !diagonal && !pure_penalty &&
                                      !geometry_changed;
            for (const unsigned int i : rows_here)
              {
                active[i] =
                  (after_update && solved[i].spring &&
                   alpha[i] == alpha_solved[i]) ?
                    law[i]->piece_of_branch(law[i]
                                              ->next_piece(solved[i],
                                                           p[i],
                                                           mu_solved[i],
                                                           alpha_solved[i])
                                              .branch,
                                            mu[i],
                                            alpha[i]) :
                    law[i]->next_piece(solved[i], p[i], mu[i], alpha[i]);
                branches[i] = active[i].branch;
                e[i]        = active[i].relation(p[i]) - balanced[i];
              }
            const double e_norm = ownership->norm(e);
            if (newton_steps == 0)
              initial_norm = e_norm;
            last_inner_exact = (e_norm == 0);
            // New rows (re-linearised obstacles) make the last solve stale.
            const bool stale = geometry_changed && newton_steps == 0;
            if ((e_norm == 0 && !stale) ||
                (newton_steps > 0 &&
                 (diagonal || e_norm <= eps_k * initial_norm)))
              break;
            if (newton_steps >= step_limit)
              {
                if (!tighten("inner Newton iteration of update " +
                             std::to_string(history.size() + 1) +
                             " reached Maximum Newton steps"))
                  break;
                step_limit += max_newton_steps;
              }
            // A piece depends only on its branches (mu, alpha are fixed
            // here): a set seen before in this inner solve means Newton
            // cycles.
            const std::vector<unsigned int> branches_here =
              part_of(branches, rows_here);
            if (!solved_sets.insert(branches_here))
              {
                // In exact arithmetic the smooth pieces cannot cycle; with
                // CG the residual may no longer fix p to the digits the
                // laws compare (Hertz refinement 10 at 1e-12). Tighten it
                // and solve this set again, or give up.
                if (!tighten("inner Newton iteration of update " +
                             std::to_string(history.size() + 1) +
                             " came back to a released set it had solved"))
                  {
                    cycled                 = true;
                    cycle_linear_tolerance = path.statistics.tolerance;
                    break;
                  }
                solved_sets.clear();
                solved_sets.insert(branches_here);
              }
            // After a carried start, the rows that keep their branch take
            // the multiplier update (eq. 48) with the step that switches the
            // others: the carried multipliers are the coarser level's (its
            // springs' w - g, interpolated at new nodes), so the update would
            // otherwise cost a solve of its own once the set has settled
            // (Hertz refinement 7: 3 fine solves instead of 4, the last
            // ||pbar|| 1.9e-3 instead of 40 before its update). A row that
            // switches keeps the multiplier its switch was read with.
            if (update_carried_multipliers && started && k == 1 && !diagonal &&
                !pure_penalty)
              for (const unsigned int i : rows_here)
                if (law[i]->has_multiplier() && branches[i] == solved[i].branch)
                  {
                    mu[i] = law[i]->gradient(p[i], mu[i], alpha[i]);
                    active[i] =
                      law[i]->piece_of_branch(branches[i], mu[i], alpha[i]);
                  }
            path.solve(active, p);
            for (const unsigned int i : rows_here)
              balanced[i] = active[i].relation(p[i]);
            solved = active;
            ++newton_steps;
            ++total_newton_steps;
          }
        if (cycled)
          break;
      }
    log << "  augmented Lagrangian "
        << (converged ? "converged" : "did NOT converge") << " after "
        << history.size() << " multiplier updates, " << total_newton_steps
        << " Newton steps" << std::endl;
    return converged;
  }

  bool
  AugmentedLagrangianSolver::solve_displacement(
    const EquilibriumSystem &system,
    const std::vector<bool> &unilateral,
    NewtonStepPath          &path,
    const Timer             &timer,
    std::ostream            &log)
  {
    // Eq. 29 on the rows: gamma_i >= 0 is the reaction -p_i, beta_i a
    // stiffness on the penetration w_i - g_i. A row is in contact when
    // gamma + beta (w - g) > 0: a spring of stiffness beta anchored at
    // g - gamma/beta (in the path's terms: compliance 1/beta, mu =
    // -gamma/beta); otherwise it carries nothing (compliance infinity, so
    // the path adds no spring). Bilateral rows stay held at w_n = g. Start:
    // gamma from the trial reactions, w_n = g.
    const unsigned int               nq        = unilateral.size();
    const std::vector<unsigned int> &rows_here = ownership->relevant();
    const double                     beta0     = 1. / initial_alpha;
    std::vector<double> gamma(nq, 0.), beta(nq, beta0), gap(nq, 0.);
    for (const unsigned int i : rows_here)
      if (unilateral[i])
        gamma[i] = std::max(0., -p[i]);

    std::vector<bool> contact(nq), contact_previous(nq, true),
      solved_contact(nq, true);
    std::vector<double> path_mu(nq, 0.), path_alpha(nq, 1.), w(nq);
    std::vector<double> balanced(nq, 0.), change(nq, 0.),
      change_previous(nq, 0.);
    double       norm_previous = std::numeric_limits<double>::max();
    double       eps_previous  = eps_max;
    double       eps_k         = eps_max;
    bool         first         = true;
    const double infinity      = std::numeric_limits<double>::infinity();
    bool         beta_grew     = false;

    // The spring force the current set and gap ask for at row i.
    auto spring_force = [&](const unsigned int i) {
      return gamma[i] + beta[i] * gap[i];
    };

    for (unsigned int k = 1;; ++k)
      {
        // Step 3: Newton steps on u for fixed gamma, beta (the diagonal
        // scheme: one).
        unsigned int                  newton_steps = 0;
        double                        initial_norm = 0;
        SolvedSets<std::vector<bool>> solved_sets(*ownership);
        for (;;)
          {
            std::vector<double> e(nq);
            for (const unsigned int i : rows_here)
              {
                contact[i] = !unilateral[i] || spring_force(i) > 0;
                const double term =
                  (unilateral[i] && contact[i]) ? spring_force(i) : 0.;
                e[i] = unilateral[i] ? term - balanced[i] : 0.;
              }
            const double e_norm = first ? 1. : ownership->norm(e);
            if (newton_steps == 0)
              initial_norm = e_norm;
            if (e_norm == 0 ||
                (newton_steps > 0 &&
                 (diagonal || e_norm <= eps_k * initial_norm)) ||
                newton_steps >= max_newton_steps)
              break;
            // The first step after an update solves the last piece with the
            // new anchors: the set read off the old gaps and the new gamma
            // counts the penetration twice (gamma + beta (w - g) = 2 F -
            // gamma_old for a spring that carried F), and on Hertz it frees
            // every row, a piece on which the body floats.
            // (The diagonal scheme has that one step only, so it must read
            // the set afresh.)
            if (newton_steps == 0 && !first && !diagonal)
              contact = solved_contact;
            std::vector<bool> springs(nq, false);
            for (const unsigned int i : rows_here)
              if (unilateral[i])
                {
                  springs[i]    = true;
                  path_alpha[i] = contact[i] ? 1. / beta[i] : infinity;
                  path_mu[i]    = contact[i] ? -gamma[i] / beta[i] : 0.;
                }
            if (found_floating_body(
                  [&contact](const unsigned int i) { return !contact[i]; }, k))
              break;
            if (!solved_sets.insert(part_of(contact, rows_here)))
              {
                cycled = true;
                break;
              }
            path.solve(springs, path_mu, path_alpha, p);
            solved_contact = contact;
            path.contact_displacements(w);
            for (const unsigned int i : rows_here)
              {
                gap[i] = unilateral[i] ?
                           w[i] - system.rows[system.contact_rows[i]].value :
                           0.;
                balanced[i] =
                  (unilateral[i] && contact[i]) ? spring_force(i) : 0.;
              }
            first = false;
            ++newton_steps;
            ++total_newton_steps;
          }

        if (cycled || floating)
          break;
        // Step 4: gamma <- max(0, gamma + beta (w - g)) on the piece the
        // last Newton step solved: a row free there gets gamma = 0, not beta
        // times a penetration nothing resisted (with beta stiff against the
        // mesh that guess throws the body off the obstacle). The convergence
        // measure is the full one of eq. 29, max(-gamma, beta (w - g)): it
        // sees such a row penetrate.
        unsigned int changes = 0;
        for (const unsigned int i : rows_here)
          {
            change[i] =
              unilateral[i] ? std::max(-gamma[i], beta[i] * gap[i]) : 0.;
            gamma[i] = (unilateral[i] && solved_contact[i]) ?
                         std::max(0., spring_force(i)) :
                         0.;
            changes +=
              (contact[i] != contact_previous[i] && ownership->is_owned(i));
          }
        changes           = ownership->sum(changes);
        contact_previous  = contact;
        const double norm = ownership->norm(change);

        for (const unsigned int i : rows_here)
          {
            mu[i]       = unilateral[i] ? gap[i] : 0.;
            opening[i]  = mu[i];
            alpha[i]    = unilateral[i] ? 1. / beta[i] : initial_alpha;
            released[i] = unilateral[i] && !contact[i];
          }
        record(k, newton_steps, eps_k, norm, changes, timer.wall_time(), log);

        // Step 6, with the change of the reactions in place of pbar.
        if (norm < tolerance_used)
          {
            converged = true;
            break;
          }
        if (k >= max_updates)
          break;
        if (!std::isfinite(norm) || norm > 1e6 * force_scale)
          {
            diverged = true;
            break;
          }
        // The round-off floor of the change: beta times the rounding of w_n
        // (a few |w| eps per row in contact; rows out of contact change by
        // -gamma, exactly). Below it ||change|| is noise, and eq. 49 would
        // only grow beta and the noise with it: stop and say so.
        {
          double floor = 0;
          for (const unsigned int i : ownership->owned())
            if (unilateral[i] && contact[i])
              {
                const double r = 4 * std::numeric_limits<double>::epsilon() *
                                 beta[i] * std::abs(w[i]);
                floor += r * r;
              }
          roundoff_floor = std::sqrt(ownership->sum(floor));
          // An iterative solver's tolerance leaves a floor of its own (CG +
          // AMG: far above rounding): the sign is a change that grew by the
          // factor rho with beta, with the set fixed. A direct solver has no
          // such floor, and there the change may jump with beta on its way
          // down (Hertz at 24,962 dofs, diagonal: x100 at update 10, then
          // converged at update 14).
          const bool noise = path.statistics.iterative && beta_grew &&
                             changes == 0 && norm > 0.5 * rho * norm_previous;
          if (noise)
            roundoff_floor = std::max(roundoff_floor, norm_previous);
          if (norm <= roundoff_floor || noise)
            {
              roundoff_limited = true;
              break;
            }
        }
        const std::vector<double> beta_before = beta;
        if (k > 1 && !(diagonal && changes > 0) &&
            !update_penalty(
              beta, change, change_previous, norm, norm_previous, beta0))
          break;
        beta_grew       = !ownership->all(beta == beta_before);
        norm_previous   = norm;
        change_previous = change;
        eps_k           = inner_tolerance(norm, eps_previous);
      }
    log << "  augmented Lagrangian "
        << (converged ? "converged" : "did NOT converge") << " after "
        << history.size() << " multiplier updates, " << total_newton_steps
        << " Newton steps" << std::endl;
    return converged;
  }
} // namespace hrcontact
