#include <hrcontact/solvers/al/multiplier_iteration.h>

#include <limits>

namespace hrcontact
{
  using namespace dealii;

  MultiplierIteration::MultiplierIteration(AugmentedLagrangianSolver &solver,
                                           const EquilibriumSystem   &system,
                                           NewtonStepPath            &path,
                                           const Timer               &timer,
                                           const bool                 started,
                                           std::ostream              &log)
    : solver(solver)
    , state(solver.state)
    , system(system)
    , path(path)
    , ownership(path.row_partition())
    , timer(timer)
    , started(started)
    , log(log)
    , pure_penalty(solver.regularisation ==
                   AugmentedLagrangianSolver::Regularisation::pure_penalty)
    , diagonal(solver.diagonal)
    , nq(system.contact_rows.size())
    , rows_here(ownership.relevant())
    , solved(state.pieces)
    , balanced(nq, 0.)
    , pbar(nq, 0.)
    , pbar_previous(nq, 0.)
    , norm_previous(std::numeric_limits<double>::max())
    , eps_previous(solver.eps_max)
    , eps_k(solver.eps_max)
    , periodicity(ownership)
  {
    for (const unsigned int i : rows_here)
      balanced[i] = solved[i].relation(state.p[i]);
  }

  void
  MultiplierIteration::run()
  {
    for (unsigned int k = 1;; ++k)
      {
        // A carried start (start_from) begins with Newton steps on its own
        // multipliers and compliances: its first solve is not a trial whose
        // reactions could update the multipliers.
        updated = !(started && k == 1);
        if (updated && !after_solve())
          break;
        newton_steps(k);
        if (solver.flags.cycled)
          break;
      }
  }

  bool
  MultiplierIteration::tighten(const std::string &symptom)
  {
    // Inexact (CG) solves leave noise in p = Q s - q; three symptoms of it
    // tighten CG's tolerance for the remaining solves (tighten_linear_solver)
    // instead of letting the iteration fail: an inner cycle, an inner
    // iteration at its step limit, and ||pbar|| doubling while no row changed
    // its branch.
    if (!path.tighten_linear_solver())
      return false;
    log << "    " << symptom << ": CG tolerance tightened to "
        << path.statistics.tolerance << std::endl;
    return true;
  }

  double
  MultiplierIteration::constraint_residuals()
  {
    for (const unsigned int i : rows_here)
      pbar[i] =
        state.law[i]->has_multiplier() ?
          state.law[i]->residual(state.p[i], state.mu[i], state.alpha[i]) :
          0.;
    return ownership.norm(pbar);
  }

  unsigned int
  MultiplierIteration::read_pieces()
  {
    unsigned int changes = 0;
    for (const unsigned int i : rows_here)
      {
        const ContactPiece current =
          state.law[i]->piece(state.p[i], state.mu[i], state.alpha[i]);
        changes +=
          (current.branch != state.pieces[i].branch && ownership.is_owned(i));
        state.pieces[i]   = current;
        state.released[i] = state.law[i]->is_free(current.branch);
      }
    return ownership.sum(changes);
  }

  void
  MultiplierIteration::update_multipliers()
  {
    // Step 4: multiplier update (eq. 48), mu <- mu - alpha pbar =
    // dL/dp; afterwards mu = w_n - g. The pure penalty keeps mu = 0.
    // The diagonal scheme updates with the piece its single Newton step
    // solved (ConstraintLaw::multiplier_after_step): a row held there
    // (at w_n = g + offset) takes that offset,
    // since p of a held row says nothing yet about how far it moves:
    // updating mu by its reaction would guess a displacement that the
    // next step undoes, and the set then cycles (measured on lift-off).
    auto &mu = state.mu;
    if (!pure_penalty)
      for (const unsigned int i : rows_here)
        if (state.law[i]->has_multiplier())
          mu[i] = diagonal ? state.law[i]->multiplier_after_step(
                               solved[i], state.p[i], mu[i], state.alpha[i]) :
                             mu[i] - state.alpha[i] * pbar[i];
    for (const unsigned int i : rows_here)
      // w_n - g: the updated multiplier for a consistent law; released
      // rows of the pure penalty are springs anchored at the gap (mu =
      // 0), so they open by -alpha p.
      state.opening[i] =
        pure_penalty ?
          state.pieces[i].relation(state.p[i]) :
          state.law[i]->opening(state.pieces[i], state.p[i], mu[i]);
  }

  bool
  MultiplierIteration::converged(const unsigned int update,
                                 const double       norm) const
  {
    // Step 6: convergence test. The pure penalty is done once the
    // inner solve has reached its exact piece (its own answer, with the
    // tension of the released springs as its error). The diagonal
    // scheme also needs the piece at p to be the one its step solved:
    // else p satisfies another relation, and a small pbar (a stop held
    // at the estimate mu) says nothing about w.
    bool same_pieces = true;
    for (const unsigned int i : rows_here)
      same_pieces &= (state.pieces[i].branch == solved[i].branch);
    same_pieces = ownership.all(same_pieces);
    return pure_penalty ? (update > 1 && last_inner_exact) :
                          (norm <= state.tolerance_used &&
                           (!diagonal || same_pieces) && !geometry_changed);
  }

  bool
  MultiplierIteration::periodic()
  {
    std::vector<unsigned int> branches;
    for (const unsigned int i : rows_here)
      branches.push_back(state.pieces[i].branch);
    return periodicity.repeats(branches,
                               part_of(state.alpha, rows_here),
                               part_of(state.mu, rows_here));
  }

  bool
  MultiplierIteration::update_penalties(const unsigned int update,
                                        const double       norm,
                                        const unsigned int changes)
  {
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
    return !(update > 1 && !pure_penalty && !(diagonal && changes > 0) &&
             !solver.update_penalty(state.alpha,
                                    pbar,
                                    pbar_previous,
                                    norm,
                                    norm_previous,
                                    solver.initial_alpha));
  }

  bool
  MultiplierIteration::after_solve()
  {
    mu_solved    = state.mu;
    alpha_solved = state.alpha;
    // pbar with the multipliers and compliances the solve used.
    const double       norm    = constraint_residuals();
    const unsigned int changes = read_pieces();
    update_multipliers();
    solver.record(state.history.size() + 1,
                  n_newton_steps,
                  eps_k,
                  norm,
                  changes,
                  timer.wall_time(),
                  log);
    // The number of this update (k, or k - 1 after a carried start).
    const unsigned int update = state.history.size();

    auto &flags = solver.flags;
    if (converged(update, norm))
      {
        flags.converged = true;
        return false;
      }
    if (update >= solver.max_updates)
      return false;
    if (diagonal && periodic())
      {
        flags.periodic = true;
        flags.cycled   = true;
        return false;
      }
    // Floating: every row with a multiplier on its free branch and none
    // holding (a released row of the consistent AL may still carry
    // compression).
    if (solver.found_floating_body(
          [&](const unsigned int i) {
            return (!state.law[i]->has_multiplier() || state.released[i]) &&
                   !state.law[i]->holds(state.p[i]);
          },
          update))
      return false;
    // A released spring far softer than the mesh (alpha much larger
    // than the nodal compliance) leaves the body all but unsupported:
    // the solves lose every digit and ||pbar|| explodes. Stop, do not
    // iterate on garbage.
    if (diverges(norm, solver.force_scale))
      {
        flags.diverged = true;
        return false;
      }
    if (!update_penalties(update, norm, changes))
      return false;
    norm_previous = norm;
    pbar_previous = pbar;

    // Step 2.
    eps_k            = pure_penalty ? 0. : // solve the piece exactly
                           solver.inner_tolerance(norm, eps_previous);
    geometry_changed = solver.relinearisation &&
                       solver.relinearisation->relinearise(path, state.opening);
    return true;
  }

  double
  MultiplierIteration::next_pieces(std::vector<ContactPiece> &active,
                                   std::vector<unsigned int> &branches) const
  {
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
    const bool after_update = n_newton_steps == 0 && updated && !diagonal &&
                              !pure_penalty && !geometry_changed;
    const auto         &law = state.law;
    const auto         &p   = state.p;
    std::vector<double> e(nq);
    for (const unsigned int i : rows_here)
      {
        active[i] =
          (after_update && solved[i].spring &&
           state.alpha[i] == alpha_solved[i]) ?
            law[i]->piece_of_branch(
              law[i]
                ->next_piece(solved[i], p[i], mu_solved[i], alpha_solved[i])
                .branch,
              state.mu[i],
              state.alpha[i]) :
            law[i]->next_piece(solved[i], p[i], state.mu[i], state.alpha[i]);
        branches[i] = active[i].branch;
        e[i]        = active[i].relation(p[i]) - balanced[i];
      }
    return ownership.norm(e);
  }

  void
  MultiplierIteration::newton_steps(const unsigned int k)
  {
    // Step 3: Newton steps until the gradient, in contact coordinates
    // e = (w - g of the piece at p) - balanced, falls by eps_k (the
    // diagonal scheme: one step). A step that keeps every branch gives
    // e = 0 exactly: the piece is quadratic.
    n_newton_steps                                   = 0;
    unsigned int                          step_limit = solver.max_newton_steps;
    double                                initial_norm = 0;
    SolvedSets<std::vector<unsigned int>> solved_sets(ownership);
    for (;;)
      {
        std::vector<ContactPiece> active(nq);
        std::vector<unsigned int> branches(nq);
        const double              e_norm = next_pieces(active, branches);
        if (n_newton_steps == 0)
          initial_norm = e_norm;
        last_inner_exact = (e_norm == 0);
        // New rows (re-linearised obstacles) make the last solve stale.
        const bool stale = geometry_changed && n_newton_steps == 0;
        if ((e_norm == 0 && !stale) ||
            (n_newton_steps > 0 &&
             (diagonal || e_norm <= eps_k * initial_norm)))
          break;
        if (n_newton_steps >= step_limit)
          {
            if (!tighten("inner Newton iteration of update " +
                         std::to_string(state.history.size() + 1) +
                         " reached Maximum Newton steps"))
              break;
            step_limit += solver.max_newton_steps;
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
                         std::to_string(state.history.size() + 1) +
                         " came back to a released set it had solved"))
              {
                solver.flags.cycled                 = true;
                solver.flags.cycle_linear_tolerance = path.statistics.tolerance;
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
        if (solver.update_carried_multipliers && started && k == 1 &&
            !diagonal && !pure_penalty)
          for (const unsigned int i : rows_here)
            if (state.law[i]->has_multiplier() &&
                branches[i] == solved[i].branch)
              {
                state.mu[i] = state.law[i]->gradient(state.p[i],
                                                     state.mu[i],
                                                     state.alpha[i]);
                active[i]   = state.law[i]->piece_of_branch(branches[i],
                                                          state.mu[i],
                                                          state.alpha[i]);
              }
        path.solve(active, state.p);
        for (const unsigned int i : rows_here)
          balanced[i] = active[i].relation(state.p[i]);
        solved = active;
        ++n_newton_steps;
        ++state.total_newton_steps;
      }
  }
} // namespace hrcontact
