#include <deal.II/base/timer.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/al/displacement_iteration.h>
#include <hrcontact/solvers/al/multiplier_iteration.h>

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
    regularisation = get_selection<Regularisation>(
      prm,
      "Regularisation",
      {{"consistent augmented Lagrangian", Regularisation::consistent},
       {"Macaulay augmented Lagrangian", Regularisation::macaulay},
       {"pure penalty", Regularisation::pure_penalty},
       {"displacement augmented Lagrangian", Regularisation::displacement}});
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

  void
  AugmentedLagrangianSolver::record(const unsigned int k,
                                    const unsigned int newton_steps,
                                    const double       eps_k,
                                    const double       norm,
                                    const unsigned int changes,
                                    const double       seconds,
                                    std::ostream      &log)
  {
    state.p_history.push_back(state.p);
    state.mu_history.push_back(state.opening);
    state.alpha_history.push_back(state.alpha);
    state.released_history.push_back(state.released);

    AugmentedLagrangianStep step;
    step.k            = k;
    step.newton_steps = newton_steps;
    double alpha_min  = std::numeric_limits<double>::infinity();
    double alpha_max  = -alpha_min;
    for (const unsigned int i : ownership->owned())
      {
        alpha_min = std::min(alpha_min, state.alpha[i]);
        alpha_max = std::max(alpha_max, state.alpha[i]);
      }
    step.alpha_min      = ownership->min(alpha_min);
    step.alpha_max      = ownership->max(alpha_max);
    step.eps_k          = eps_k;
    step.norm_pbar      = norm;
    step.active_changes = changes;
    step.seconds        = seconds;
    state.history.push_back(step);
    state.final_norm_pbar = norm;
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
        flags.diverged = true;
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
    state.outcome = flags.outcome();
    return flags.converged;
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
    state.outcome = flags.outcome();
    return flags.converged;
  }

  void
  AugmentedLagrangianSolver::gather_state()
  {
    if (!ownership || !ownership->distributed())
      return;
    // Once per solve: the complete state for the tables, the nested
    // transfer and the next solve's start, each row from its owner.
    for (auto *v : {&state.p, &state.mu, &state.alpha, &state.opening})
      ownership->gather(*v);
    ownership->gather(state.released);
    std::vector<double> spring(state.pieces.size()),
      offset(state.pieces.size()), compliance(state.pieces.size()),
      branch(state.pieces.size());
    for (unsigned int i = 0; i < state.pieces.size(); ++i)
      {
        spring[i]     = state.pieces[i].spring;
        offset[i]     = state.pieces[i].offset;
        compliance[i] = state.pieces[i].compliance;
        branch[i]     = state.pieces[i].branch;
      }
    for (auto *v : {&spring, &offset, &compliance, &branch})
      ownership->gather(*v);
    for (unsigned int i = 0; i < state.pieces.size(); ++i)
      {
        state.pieces[i].spring     = (spring[i] != 0);
        state.pieces[i].offset     = offset[i];
        state.pieces[i].compliance = compliance[i];
        state.pieces[i].branch     = static_cast<unsigned int>(branch[i]);
      }
    for (auto *history_of :
         {&state.p_history, &state.mu_history, &state.alpha_history})
      for (auto &v : *history_of)
        ownership->gather(v);
    for (auto &v : state.released_history)
      ownership->gather(v);
  }

  bool
  AugmentedLagrangianSolver::found_floating_body(
    const std::function<bool(unsigned int)> &is_free,
    const unsigned int                       update)
  {
    const BodyHeldByContact *body =
      floating_body(held_only_by_contact, *ownership, is_free);
    if (!body)
      return false;
    flags.floating        = true;
    state.floating_update = update;
    state.floating_body   = body->name;
    return true;
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
    state.rows_owned = ownership->owned().size();
    state.rows_seen  = ownership->relevant().size();
    std::vector<bool> unilateral(nq);
    state.law.assign(nq, nullptr);
    for (unsigned int i = 0; i < nq; ++i)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        unilateral[i]             = row.unilateral && !row.law;
        state.law[i]              = &law_of(row);
      }

    Timer timer;
    state.alpha_0 = initial_alpha;
    state.mu.assign(nq, 0.);
    state.alpha.assign(nq, initial_alpha);
    state.released.assign(nq, false);
    state.opening.assign(nq, 0.);
    state.history.clear();
    state.p_history.clear();
    state.mu_history.clear();
    state.alpha_history.clear();
    state.released_history.clear();
    state.total_newton_steps = 0;
    flags                    = StopFlags();
    state.floating_body.clear();
    state.roundoff_floor = 0;

    const bool started          = has_start;
    has_start                   = false;
    state.start_origin          = started ? start.origin : std::string();
    const double measured_scale = trial_step(system, path, load_scale, started);
    log_start(nq, started, measured_scale, log);

    if (regularisation == Regularisation::displacement)
      {
        for (unsigned int i = 0; i < nq; ++i)
          if (!unilateral[i] && state.law[i]->has_multiplier())
            throw InputError(
              "Augmented Lagrangian/Regularisation = displacement augmented "
              "Lagrangian is implemented for unilateral contact only; " +
              system.describe_row(system.contact_rows[i]) + " has the law '" +
              state.law[i]->name() +
              "'. Take the consistent augmented Lagrangian.");
        DisplacementIteration(*this, system, unilateral, path, timer, log)
          .run();
      }
    else
      MultiplierIteration(*this, system, path, timer, started, log).run();
    log << "  augmented Lagrangian "
        << (flags.converged ? "converged" : "did NOT converge") << " after "
        << state.history.size() << " multiplier updates, "
        << state.total_newton_steps << " Newton steps" << std::endl;
    return flags.converged;
  }

  double
  AugmentedLagrangianSolver::trial_step(const EquilibriumSystem &system,
                                        NewtonStepPath          &path,
                                        const double             load_scale,
                                        const bool               started)
  {
    const unsigned int nq = system.contact_rows.size();
    auto              &p  = state.p;
    // Step 0: trial solution, every constraint bilateral with w_n = g; or
    // the carried state of a coarser level (start_from): its multipliers and
    // compliances, and the pieces its reactions select.
    state.pieces.assign(nq, ContactPiece());
    for (unsigned int i = 0; i < nq; ++i)
      state.pieces[i] = state.law[i]->trial_piece();
    state.scale_per_level = started ? start.scale_per_level : 0.;
    // The first carried level of nested iteration solves its own trial once
    // (every row held, as Step 0 without a start) for the force scale of
    // its tolerance, and measures how that scale shrinks per level; the
    // finer levels carry it on. Without this they would stop at a tighter
    // ||pbar|| than their own trial would set (Hertz refinement 9: 0.00159
    // instead of about 0.0035), near the solves' round-off (about 7e-4).
    double measured_scale = 0;
    if (started && start.measure_trial_scale)
      {
        path.solve(state.pieces, p);
        measured_scale = std::abs(load_scale);
        for (const unsigned int i : ownership->owned())
          measured_scale = std::max(measured_scale, std::abs(p[i]));
        measured_scale = ownership->max(measured_scale);
        if (start.tolerance_scale > 0)
          state.scale_per_level =
            std::min(1.,
                     std::max(start.smallest_scale_per_level,
                              measured_scale / start.tolerance_scale));
      }
    if (started)
      {
        AssertThrow(start.fits(system),
                    ExcMessage("the carried contact state does not fit the "
                               "rows of this system"));
        for (const unsigned int i : ownership->relevant())
          if (state.law[i]->has_multiplier())
            {
              state.mu[i] = start.mu[i];
              state.alpha[i] =
                (start.alpha[i] > 0) ? start.alpha[i] : initial_alpha;
              state.pieces[i] =
                state.law[i]->piece(start.p[i], state.mu[i], state.alpha[i]);
            }
      }
    path.solve(state.pieces, p);

    double scale = std::abs(load_scale);
    for (const unsigned int i : ownership->owned())
      scale = std::max(scale, std::abs(p[i]));
    scale = ownership->max(scale);
    if (measured_scale > 0)
      scale = std::max(scale, measured_scale);
    else if (started)
      scale = std::max(scale, start.tolerance_scale);
    state.tolerance_scale = scale;
    state.tolerance_used =
      std::max(absolute_tolerance, relative_tolerance * scale);
    force_scale = std::max(scale, 1e-300);
    return measured_scale;
  }

  void
  AugmentedLagrangianSolver::log_start(const unsigned int nq,
                                       const bool         started,
                                       const double       measured_scale,
                                       std::ostream      &log) const
  {
    const bool pure_penalty = (regularisation == Regularisation::pure_penalty);
    // Three digits on this line, whatever the stream held before.
    const std::streamsize precision = log.precision(3);
    // Under MPI: how the rows are shared (reductions on every process).
    std::string shares;
    if (ownership->distributed())
      {
        const double owned = state.rows_owned, seen = state.rows_seen;
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
    log << ", tolerance " << state.tolerance_used;
    if (measured_scale > 0)
      log << " (this level's trial reactions, " << state.scale_per_level
          << " of the coarser level's)";
    else if (started && start.scale_per_level > 0)
      log << " (the trial reactions carried at " << start.scale_per_level
          << " per level)";
    if (started)
      log << ", started from " << start.origin;
    log << std::endl;
    log.precision(precision);
  }
} // namespace hrcontact
