#ifndef hrcontact_al_augmented_lagrangian_solver_h
#define hrcontact_al_augmented_lagrangian_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/al/stopping_tests.h>
#include <hrcontact/solvers/contact_iteration.h>
#include <hrcontact/solvers/nested_iteration.h>
#include <hrcontact/solvers/newton_step_path.h>
#include <hrcontact/solvers/row_relinearisation.h>

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace hrcontact
{
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
   *
   * The state it iterates on is a ContactIteration member; result() hands
   * it out read-only. The iteration itself runs in MultiplierIteration
   * (consistent, Macaulay, pure penalty; classical or diagonal) or in
   * DisplacementIteration (eq. 29), after the trial solve of Step 0 here;
   * the stopping tests are in al/stopping_tests, the messages in
   * al/outcome_messages.cc.
   *
   * Under MPI each process updates the rows of its owned and ghost nodes
   * (ContactRowPartition, from the path), from the p their owners
   * computed; norms, counts and decisions are reductions over the owned
   * rows, and the result is gathered once at the end of a solve.
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

    /**
     * The same, with constraint rows that follow the configuration: after
     * every update that did not converge, before the next Newton steps,
     * `relinearisation.relinearise` is called (curved obstacles at the
     * current configuration).
     */
    bool
    solve(const EquilibriumSystem &system,
          NewtonStepPath          &path,
          const double             load_scale,
          RowRelinearisation      &relinearisation,
          std::ostream            &log);

    /**
     * Start the next solve from `start` (one entry per Q row: mu, alpha and
     * a reaction estimate that selects the first pieces) instead of the
     * trial solution of Step 0: the nested iteration's coarser level. Used
     * by one solve only. Not for the pure penalty or the displacement
     * augmented Lagrangian, which have no such state.
     */
    void
    start_from(const ContactStart &start);

    /** The start the next solve takes (start_from), if one is pending. */
    std::optional<ContactStart>
    pending_start() const
    {
      return has_start ? std::optional<ContactStart>(start) : std::nullopt;
    }

    /** Start the next solve from the last solve's multipliers, penalties,
     * reactions and force scale (a material Newton step's contact solve). */
    void
    start_from_result(const std::string &origin)
    {
      ContactStart start;
      start.mu              = result().mu;
      start.alpha           = result().alpha;
      start.p               = result().p;
      start.tolerance_scale = result().tolerance_scale;
      start.scale_per_level = result().scale_per_level;
      start.origin          = origin;
      start_from(start);
    }

    /** The state, history and outcome of the last solve. */
    const ContactIteration &
    result() const
    {
      return state;
    }

    /**
     * One message naming why the last solve did not converge and what to
     * change, for the error the run ends with; `free_rigid_motions` (the
     * motions only the contacts hold) adds a hint about mechanisms.
     * Empty when it converged.
     */
    std::string
    outcome_message(const unsigned int free_rigid_motions) const;

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

    /** Whether a solve leaves multipliers a later one can start from: the
     * consistent and the Macaulay AL (start_from). */
    bool
    carries_state() const
    {
      return regularisation == Regularisation::consistent ||
             regularisation == Regularisation::macaulay;
    }
    /**
     * Section 4.4: classical (inner Newton to eps_k, then one multiplier
     * update) or diagonal (one Newton step, then one multiplier update).
     */
    bool         diagonal = false;
    double       eps_min = 1e-12, eps_max = 1e-2;
    double       absolute_tolerance = 0, relative_tolerance = 1e-10;
    unsigned int max_updates = 100, max_newton_steps = 50;
    /** Whether the Newton steps after a carried start also update the
     * multipliers of the rows that keep their branch (eq. 48). */
    bool   update_carried_multipliers = true;
    double max_penalty_growth         = 1e16;

    /**
     * The law of a Q row: the row's own law (EquilibriumRow::law), else
     * unilateral contact regularised as Regularisation says (consistent or
     * Macaulay) for a unilateral row, else a bilateral constraint.
     */
    const ConstraintLaw &
    law_of(const EquilibriumRow &row) const;

    using BodyHeldByContact = hrcontact::BodyHeldByContact;

    /**
     * Set before solve: the bodies whose rigid-body motions are held by
     * contact rows only (rigid_motions_held_only_by_contact_by_body > 0).
     * An update that finds every row of one of them released (none
     * holding), without having converged, means the loads pull that body
     * off: the solve stops with SolveOutcome::floating.
     */
    std::vector<BodyHeldByContact> held_only_by_contact;

  private:
    friend class MultiplierIteration;
    friend class DisplacementIteration;

    /** The iteration itself; solve() sets the outcome from its flags. */
    bool
    iterate(const EquilibriumSystem &system,
            NewtonStepPath          &path,
            const double             load_scale,
            std::ostream            &log);

    /**
     * Step 0: the trial solution, every row on its law's trial piece (held
     * at w_n = g); or the carried state of a coarser level (start_from):
     * its multipliers and compliances, and the pieces its reactions select.
     * Sets the tolerance from the load and the trial reactions; returns the
     * force scale this level measured with a trial solve of its own (0: not
     * measured).
     */
    double
    trial_step(const EquilibriumSystem &system,
               NewtonStepPath          &path,
               const double             load_scale,
               const bool               started);

    /** The line that opens a solve in the log. */
    void
    log_start(const unsigned int n_rows,
              const bool         started,
              const double       measured_scale,
              std::ostream      &log) const;

    /**
     * The iteration computes the rows each process sees; afterwards every
     * entry of the state and its history is gathered from the owner of its
     * row, so that the result is complete on every process.
     */
    void
    gather_state();

    /** Which rows this process owns and sees: the running path's. */
    const ContactRowPartition *ownership = nullptr;

    /**
     * Whether some body of held_only_by_contact has every row free
     * (`is_free`, by index into contact_rows); if so, set floating, the
     * update and the body.
     */
    bool
    found_floating_body(const std::function<bool(unsigned int)> &is_free,
                        const unsigned int                       update);

    /** The state the iteration works on and hands out (result()). */
    ContactIteration state;

    /** The start of the next solve (start_from), if any. */
    ContactStart start;
    bool         has_start = false;

    /** The relinearisation of the running solve, or null. */
    RowRelinearisation *relinearisation = nullptr;

    /** How the last solve stopped (see SolveOutcome). */
    StopFlags flags;
    /** Why the smooth pieces of the inner iteration cycled. */
    std::string
    cycle_cause() const;

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
