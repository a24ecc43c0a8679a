#ifndef hrcontact_contact_iteration_h
#define hrcontact_contact_iteration_h

#include <hrcontact/constraints/constraint_law.h>

#include <string>
#include <vector>

namespace hrcontact
{
  /** One row of history.csv: one multiplier update. */
  struct AugmentedLagrangianStep
  {
    unsigned int k            = 0;
    unsigned int newton_steps = 0;
    double       alpha_min = 0, alpha_max = 0, eps_k = 0, norm_pbar = 0;
    unsigned int active_changes = 0;
    double       seconds        = 0;
  };

  /**
   * How a contact iteration ended. Every outcome but `converged` is an
   * error of the run (exit code 3) after all result files were written
   * with converged = false; AugmentedLagrangianSolver::outcome_message
   * names the cause and the remedy.
   */
  enum class SolveOutcome
  {
    /** ||pbar|| fell below the tolerance (Step 6). */
    converged,
    /** Maximum multiplier updates reached. */
    iteration_limit,
    /** ||pbar|| exploded, or alpha would exceed its allowed growth. */
    diverged,
    /** An inner Newton iteration came back to a released set it had
     * solved. */
    inner_cycle,
    /** The diagonal scheme reproduced an earlier update: it is periodic. */
    periodic,
    /** Every contact released while only contacts hold the body. */
    floating,
    /** The displacement AL reached its round-off floor. */
    roundoff_limited
  };

  /**
   * What the augmented Lagrangian iteration (section 4.4) leaves behind: one
   * entry per Q row of the final state, the per-update history, and the
   * outcome. Read through Results::contact; the solver fills it.
   */
  struct ContactIteration
  {
    // One entry per Q row (bilateral rows: mu = 0, always pressed).
    std::vector<double> p, mu, alpha;
    /** Whether the row's piece at p is its law's free branch (released). */
    std::vector<bool> released;
    /** The law of each row during the last solve. */
    std::vector<const ConstraintLaw *> law;
    /** The piece (and branch) of each row at p after the last update. */
    std::vector<ContactPiece> pieces;
    /**
     * w_n - g per Q row after the last update: mu for the consistent AL
     * (pressed rows have mu = 0), mu or 0 (pressed) for the Macaulay AL, the
     * measured value for the displacement AL.
     */
    std::vector<double>                  opening;
    std::vector<AugmentedLagrangianStep> history;
    /** Per multiplier update k: p of the solve, w_n - g after the update
     * (the opening), alpha used (1/beta for the displacement AL), and the
     * released flags. */
    std::vector<std::vector<double>> p_history, mu_history, alpha_history;
    std::vector<std::vector<bool>>   released_history;

    /**
     * This process's share of the rows under MPI (ContactRowPartition): the
     * rows of the nodes it owns, whose p it computed, and those it updated
     * (owned and ghost). Every row on one process.
     */
    unsigned int rows_owned = 0, rows_seen = 0;

    /** Where the last solve started (ContactStart::origin), empty: from
     * the trial solution. */
    std::string start_origin;

    /** The initial compliance alpha_0 the iteration started from. */
    double alpha_0 = 0;

    SolveOutcome outcome = SolveOutcome::iteration_limit;
    bool
    converged() const
    {
      return outcome == SolveOutcome::converged;
    }
    /** The multiplier update during which floating was detected. */
    unsigned int floating_update = 0;
    /** The body found floating ("body 3"; empty in a one-body scene). */
    std::string floating_body;
    /** Displacement AL: the noise floor of ||change|| it stopped at. */
    double       roundoff_floor     = 0;
    unsigned int total_newton_steps = 0;
    double       final_norm_pbar    = 0;
    double       tolerance_used     = 0;
    /** The force the relative tolerance is measured against (the load and
     * the first solve's reactions). */
    double tolerance_scale = 0;
    /** Nested iteration: how much the trial reactions' scale shrinks per
     * level of refinement, measured on the first carried level (0: not
     * measured; see ContactStart::measure_trial_scale). */
    double scale_per_level = 0;
  };
} // namespace hrcontact

#endif
