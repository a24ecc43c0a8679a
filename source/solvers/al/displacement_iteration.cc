#include <hrcontact/solvers/al/displacement_iteration.h>
#include <hrcontact/solvers/al/stopping_tests.h>

#include <cmath>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  DisplacementIteration::DisplacementIteration(
    AugmentedLagrangianSolver &solver,
    const EquilibriumSystem   &system,
    const std::vector<bool>   &unilateral,
    NewtonStepPath            &path,
    const Timer               &timer,
    std::ostream              &log)
    : solver(solver)
    , state(solver.state)
    , system(system)
    , unilateral(unilateral)
    , path(path)
    , ownership(path.row_partition())
    , timer(timer)
    , log(log)
    , nq(unilateral.size())
    , rows_here(ownership.relevant())
    , beta0(1. / solver.initial_alpha)
    , gamma(nq, 0.)
    , beta(nq, beta0)
    , gap(nq, 0.)
    , contact(nq)
    , contact_previous(nq, true)
    , solved_contact(nq, true)
    , path_mu(nq, 0.)
    , path_alpha(nq, 1.)
    , w(nq)
    , balanced(nq, 0.)
    , change(nq, 0.)
    , change_previous(nq, 0.)
    , norm_previous(std::numeric_limits<double>::max())
    , eps_previous(solver.eps_max)
    , eps_k(solver.eps_max)
  {
    for (const unsigned int i : rows_here)
      if (unilateral[i])
        gamma[i] = std::max(0., -state.p[i]);
  }

  unsigned int
  DisplacementIteration::newton_steps(const unsigned int k)
  {
    // Step 3: Newton steps on u for fixed gamma, beta (the diagonal
    // scheme: one).
    const double infinity     = std::numeric_limits<double>::infinity();
    unsigned int n            = 0;
    double       initial_norm = 0;
    SolvedSets<std::vector<bool>> solved_sets(ownership);
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
        const double e_norm = first ? 1. : ownership.norm(e);
        if (n == 0)
          initial_norm = e_norm;
        if (e_norm == 0 ||
            (n > 0 && (solver.diagonal || e_norm <= eps_k * initial_norm)) ||
            n >= solver.max_newton_steps)
          break;
        // The first step after an update solves the last piece with the
        // new anchors: the set read off the old gaps and the new gamma
        // counts the penetration twice (gamma + beta (w - g) = 2 F -
        // gamma_old for a spring that carried F), and on Hertz it frees
        // every row, a piece on which the body floats.
        // (The diagonal scheme has that one step only, so it must read
        // the set afresh.)
        if (n == 0 && !first && !solver.diagonal)
          contact = solved_contact;
        std::vector<bool> springs(nq, false);
        for (const unsigned int i : rows_here)
          if (unilateral[i])
            {
              springs[i]    = true;
              path_alpha[i] = contact[i] ? 1. / beta[i] : infinity;
              path_mu[i]    = contact[i] ? -gamma[i] / beta[i] : 0.;
            }
        if (solver.found_floating_body(
              [this](const unsigned int i) { return !contact[i]; }, k))
          break;
        if (!solved_sets.insert(part_of(contact, rows_here)))
          {
            solver.flags.cycled = true;
            break;
          }
        path.solve(springs, path_mu, path_alpha, state.p);
        solved_contact = contact;
        path.contact_displacements(w);
        for (const unsigned int i : rows_here)
          {
            gap[i]      = unilateral[i] ?
                            w[i] - system.rows[system.contact_rows[i]].value :
                            0.;
            balanced[i] = (unilateral[i] && contact[i]) ? spring_force(i) : 0.;
          }
        first = false;
        ++n;
        ++state.total_newton_steps;
      }
    return n;
  }

  unsigned int
  DisplacementIteration::update_multipliers()
  {
    // Step 4: gamma <- max(0, gamma + beta (w - g)) on the piece the
    // last Newton step solved: a row free there gets gamma = 0, not beta
    // times a penetration nothing resisted (with beta stiff against the
    // mesh that guess throws the body off the obstacle). The convergence
    // measure is the full one of eq. 29, max(-gamma, beta (w - g)): it
    // sees such a row penetrate.
    unsigned int changes = 0;
    for (const unsigned int i : rows_here)
      {
        change[i] = unilateral[i] ? std::max(-gamma[i], beta[i] * gap[i]) : 0.;
        gamma[i]  = (unilateral[i] && solved_contact[i]) ?
                      std::max(0., spring_force(i)) :
                      0.;
        changes += (contact[i] != contact_previous[i] && ownership.is_owned(i));
      }
    changes          = ownership.sum(changes);
    contact_previous = contact;
    return changes;
  }

  bool
  DisplacementIteration::at_roundoff_floor(const unsigned int changes,
                                           const double       norm)
  {
    // The round-off floor of the change: beta times the rounding of w_n
    // (a few |w| eps per row in contact; rows out of contact change by
    // -gamma, exactly). Below it ||change|| is noise, and eq. 49 would
    // only grow beta and the noise with it: stop and say so.
    double floor = 0;
    for (const unsigned int i : ownership.owned())
      if (unilateral[i] && contact[i])
        {
          const double r = 4 * std::numeric_limits<double>::epsilon() *
                           beta[i] * std::abs(w[i]);
          floor += r * r;
        }
    state.roundoff_floor = std::sqrt(ownership.sum(floor));
    // An iterative solver's tolerance leaves a floor of its own (CG +
    // AMG: far above rounding): the sign is a change that grew by the
    // factor rho with beta, with the set fixed. A direct solver has no
    // such floor, and there the change may jump with beta on its way
    // down (Hertz at 24,962 dofs, diagonal: x100 at update 10, then
    // converged at update 14).
    const bool noise = path.statistics.iterative && beta_grew && changes == 0 &&
                       norm > 0.5 * solver.rho * norm_previous;
    if (noise)
      state.roundoff_floor = std::max(state.roundoff_floor, norm_previous);
    return norm <= state.roundoff_floor || noise;
  }

  void
  DisplacementIteration::run()
  {
    auto &flags = solver.flags;
    for (unsigned int k = 1;; ++k)
      {
        const unsigned int steps = newton_steps(k);
        if (flags.cycled || flags.floating)
          break;
        const unsigned int changes = update_multipliers();
        const double       norm    = ownership.norm(change);
        for (const unsigned int i : rows_here)
          {
            state.mu[i]      = unilateral[i] ? gap[i] : 0.;
            state.opening[i] = state.mu[i];
            state.alpha[i] =
              unilateral[i] ? 1. / beta[i] : solver.initial_alpha;
            state.released[i] = unilateral[i] && !contact[i];
          }
        solver.record(k, steps, eps_k, norm, changes, timer.wall_time(), log);

        // Step 6, with the change of the reactions in place of pbar.
        if (norm < state.tolerance_used)
          {
            flags.converged = true;
            break;
          }
        if (k >= solver.max_updates)
          break;
        if (diverges(norm, solver.force_scale))
          {
            flags.diverged = true;
            break;
          }
        if (at_roundoff_floor(changes, norm))
          {
            flags.roundoff_limited = true;
            break;
          }
        // Step 5 (eq. 49), and Step 2.
        const std::vector<double> beta_before = beta;
        if (k > 1 && !(solver.diagonal && changes > 0) &&
            !solver.update_penalty(
              beta, change, change_previous, norm, norm_previous, beta0))
          break;
        beta_grew       = !ownership.all(beta == beta_before);
        norm_previous   = norm;
        change_previous = change;
        eps_k           = solver.inner_tolerance(norm, eps_previous);
      }
  }
} // namespace hrcontact
