#ifndef hrcontact_augmented_lagrangian_solver_h
#define hrcontact_augmented_lagrangian_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/newton_step.h>

#include <functional>
#include <ostream>
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
   * Frictionless unilateral contact by the consistent augmented Lagrangian of
   * section 4.4, on the reduced unknowns s0 of the EquilibriumReduction.
   *
   * Per unilateral constraint i: multiplier mu_i (meaning w_n - g) and
   * compliance alpha_i > 0; L = mu pbar - alpha pbar^2 / 2 with
   * pbar = max(p, mu/alpha) (eq. 26), C^1 and concave in p. Delta_i = 1
   * ("released": a spring of stiffness 1/alpha anchored at g + mu) iff
   * p_i > mu_i/alpha_i, else 0 ("pressed": w_n = g exactly).
   *
   * Trial solution: every constraint bilateral, w_n = g. Then Steps 2-6:
   * inexact Newton on s0 (gradient eq. 46, Hessian -(M0 + (QR)^T alpha Delta
   * QR), eq. 47) to the tolerance eps_k, multiplier update mu <- mu -
   * alpha pbar (eq. 48), penalty update alpha <- rho alpha if ||pbar|| >
   * delta ||pbar_prev|| (eq. 49), stop when ||pbar|| < tol.
   *
   * Each Newton step is an exact solve of the quadratic piece selected by the
   * released set, by either NewtonStepPath (null-space or condensed); the
   * solver only sees p, so both paths take the same decisions. After an
   * exact solve with the set A_old, the gradient of eq. 46 is (QR)^T e with
   * e_i = [i in A](mu_i - alpha_i p_i) - [i in A_old](mu_old_i - alpha_old_i
   * p_i): eps_k is applied to |e|, the gradient in contact coordinates.
   */
  class AugmentedLagrangianSolver
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm, const Constants &constants);

    /**
     * The nodal compliance c_h of the mesh and material (see the Initial
     * penalty scaling entry); sets initial_alpha.
     */
    void
    set_nodal_compliance(const double c);

    /**
     * Solve with the given Newton-step path. `load_scale` (a force) makes the
     * relative tolerance and eps_k unit free. Returns true when converged;
     * the path then holds the final stresses and displacements.
     */
    bool
    solve(const EquilibriumSystem &system,
          NewtonStepPath          &path,
          const double             load_scale,
          std::ostream            &log);

    // Parameters (section 4.4, Step 1).
    /**
     * alpha_0 from Initial penalty: times the nodal compliance c_h when
     * scale_by_compliance (call set_nodal_compliance before solve).
     */
    double initial_alpha       = 1e-3;
    double initial_penalty     = 1e4;
    bool   scale_by_compliance = true;
    double nodal_compliance    = 0;
    double rho                 = 10;
    double delta               = 0.25;
    bool   per_constraint      = false;
    /**
     * The regularisation of the unilateral constraint (section 3.3):
     * consistent: the paper's eq. 26/28, pbar = max(p, mu/alpha);
     * macaulay: eq. 27 on the same constraint p <= 0, pbar = (p)_+;
     * pure_penalty: mu = 0 and alpha fixed, one exact piece;
     * displacement: eq. 29, multiplier gamma (a reaction) and stiffness beta
     * on w_n - g (needs the condensed path).
     */
    enum class Regularisation
    {
      consistent,
      macaulay,
      pure_penalty,
      displacement
    };
    Regularisation regularisation = Regularisation::consistent;
    /**
     * Section 4.4: classical (inner Newton to eps_k, then one multiplier
     * update) or diagonal (one Newton step, then one multiplier update).
     */
    bool         diagonal = false;
    double       eps_min = 1e-12, eps_max = 1e-2;
    double       absolute_tolerance = 0, relative_tolerance = 1e-10;
    unsigned int max_updates = 100, max_newton_steps = 50;
    double       max_penalty_growth = 1e16;

    /**
     * The law of a Q row: the row's own law (EquilibriumRow::law), else
     * unilateral contact regularised as Regularisation says (consistent or
     * Macaulay) for a unilateral row, else a bilateral constraint.
     */
    const ConstraintLaw &
    law_of(const EquilibriumRow &row) const;

    /**
     * Called after every multiplier update that did not converge, before
     * the next Newton steps (curved obstacles re-linearised at the current
     * configuration). Returns whether it changed the rows: the next update
     * then solves at least once, and convergence waits for a call that
     * changed nothing.
     */
    std::function<bool()> after_update;

    // Results, one entry per Q row (bilateral rows: mu = 0, always pressed).
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
    bool                             converged = false;
    /** ||pbar|| became non-finite or exceeded 1e6 x the load scale, or alpha
     * would grow beyond max_penalty_growth x initial_alpha. */
    bool diverged = false;
    /**
     * An inner Newton iteration met a released set it had already solved:
     * Newton cycles between pieces and would never reach eps_k (the kink of
     * the Macaulay bracket at p = 0 does this).
     */
    bool cycled = false;
    /**
     * Set with cycled when the diagonal scheme, not an inner Newton solve,
     * came back to the state (branches, alpha, mu) of an earlier
     * update: the multiplier iteration itself is periodic.
     */
    bool periodic = false;
    /**
     * Set before solve: some rigid-body motion of the body is held by
     * unilateral contacts only (rigid_motions_held_only_by_contact > 0).
     * Then an update that finds every unilateral row released, without
     * having converged, means the loads pull the body off its obstacles:
     * the solve stops with `floating`.
     */
    bool held_only_by_contact = false;
    /**
     * Displacement AL: ||change|| fell to its round-off floor (beta times
     * the rounding of w_n) above the tolerance: stopped, not converged.
     */
    bool   roundoff_limited = false;
    double roundoff_floor   = 0;
    bool   floating         = false;
    /** The multiplier update during which floating was detected. */
    unsigned int floating_update    = 0;
    unsigned int total_newton_steps = 0;
    double       final_norm_pbar    = 0;
    double       tolerance_used     = 0;

  private:
    /** The displacement AL of eq. 29 (Regularisation = displacement). */
    bool
    solve_displacement(const EquilibriumSystem &system,
                       const std::vector<bool> &unilateral,
                       NewtonStepPath          &path,
                       const dealii::Timer     &timer,
                       std::ostream            &log);
    /** Append a row to history and print it. */
    void
    record(const unsigned int k,
           const unsigned int newton_steps,
           const double       eps_k,
           const double       norm,
           const unsigned int changes,
           const double       seconds,
           std::ostream      &log);
    /**
     * Penalty update of eq. 49 on `penalty` (alpha, or beta for the
     * displacement AL) from the constraint residual r; false when the growth
     * limit was hit (then diverged is set).
     */
    bool
    update_penalty(std::vector<double>       &penalty,
                   const std::vector<double> &r,
                   const std::vector<double> &r_previous,
                   const double               norm,
                   const double               norm_previous,
                   const double               initial);
    /** eps_k of Step 2 from the relative residual. */
    double
    inner_tolerance(const double norm, double &eps_previous) const;

    double force_scale = 1;
  };
} // namespace hrcontact

#endif
