#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>

#include <sstream>

// The messages a solve that did not converge ends the run with: the cause
// (SolveOutcome) and what to change.

namespace hrcontact
{
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
    switch (state.outcome)
      {
        case SolveOutcome::converged:
          return "";
        case SolveOutcome::floating:
          // In a scene of several bodies: the floating one's motions.
          for (const auto &body : held_only_by_contact)
            if (!state.floating_body.empty() &&
                body.name == state.floating_body)
              free_rigid_motions = body.free_motions;
          return "every contact constraint" +
                 (state.floating_body.empty() ? std::string() :
                                                " of " + state.floating_body) +
                 " released at multiplier update " +
                 std::to_string(state.floating_update) +
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
            << state.history.size() << ": the change of the reactions, "
            << state.final_norm_pbar
            << ", has reached the noise floor that the rounding of the "
               "displacements and the linear solver's tolerance leave at this "
               "stiffness (about "
            << state.roundoff_floor << "), above the tolerance "
            << state.tolerance_used
            << ". Loosen Augmented Lagrangian/Relative tolerance, reduce "
               "Initial penalty, or tighten Linear solver/Tolerance. Results "
               "were written with converged = false.";
          return s.str();
        case SolveOutcome::periodic:
          return "the diagonal scheme cycles: multiplier update " +
                 std::to_string(state.history.size()) +
                 " reproduced an earlier update (the same branches, penalties "
                 "and multipliers), so the iteration is periodic and would "
                 "never converge. Take Augmented Lagrangian/Iteration scheme = "
                 "classical, or another Initial penalty." +
                 mechanism_hint +
                 " Results were written with converged = false.";
        case SolveOutcome::inner_cycle:
          return "the inner Newton iteration of multiplier update " +
                 std::to_string(state.history.size() + 1) +
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
            << state.history.size()
            << " without converging: ||pbar|| = " << state.final_norm_pbar
            << " either exceeds a million times the load scale or would need "
               "alpha beyond Maximum penalty growth x Initial penalty (alpha "
               "is "
            << state.alpha.front()
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
            << state.history.size()
            << " multiplier updates (Augmented Lagrangian/Maximum multiplier "
               "updates): ||pbar|| = "
            << state.final_norm_pbar << " > tolerance " << state.tolerance_used
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
    if (flags.cycle_linear_tolerance > 0)
      s << "CG was tightened to " << flags.cycle_linear_tolerance
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
} // namespace hrcontact
