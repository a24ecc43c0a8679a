#ifndef hrcontact_al_displacement_iteration_h
#define hrcontact_al_displacement_iteration_h

#include <deal.II/base/timer.h>

#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <ostream>
#include <vector>

namespace hrcontact
{
  /**
   * The displacement augmented Lagrangian of eq. 29 (Regularisation =
   * displacement) on the rows: gamma_i >= 0 is the reaction -p_i, beta_i a
   * stiffness on the penetration w_i - g_i. A row is in contact when gamma +
   * beta (w - g) > 0: a spring of stiffness beta anchored at g - gamma/beta
   * (in the path's terms: compliance 1/beta, mu = -gamma/beta); otherwise it
   * carries nothing (compliance infinity, so the path adds no spring).
   * Bilateral rows stay held at w_n = g. Start: gamma from the trial
   * reactions, w_n = g. Needs the normal displacements of the rows
   * (NewtonStepPath::contact_displacements: the condensed path).
   */
  class DisplacementIteration
  {
  public:
    DisplacementIteration(AugmentedLagrangianSolver &solver,
                          const EquilibriumSystem   &system,
                          const std::vector<bool>   &unilateral,
                          NewtonStepPath            &path,
                          const dealii::Timer       &timer,
                          std::ostream              &log);

    /** Iterate until a stopping test ends it (the solver's flags). */
    void
    run();

  private:
    /** Step 3 of update k: Newton steps on u for fixed gamma, beta; the
     * count. */
    unsigned int
    newton_steps(const unsigned int k);
    /** Step 4 on the piece the last Newton step solved; the number of rows
     * whose contact status changed. */
    unsigned int
    update_multipliers();
    /** Whether ||change|| reached the round-off floor of the solves. */
    bool
    at_roundoff_floor(const unsigned int changes, const double norm);
    /** The spring force the current set and gap ask for at row i. */
    double
    spring_force(const unsigned int i) const
    {
      return gamma[i] + beta[i] * gap[i];
    }

    AugmentedLagrangianSolver       &solver;
    ContactIteration                &state;
    const EquilibriumSystem         &system;
    const std::vector<bool>         &unilateral;
    NewtonStepPath                  &path;
    const ContactRowPartition       &ownership;
    const dealii::Timer             &timer;
    std::ostream                    &log;
    const unsigned int               nq;
    const std::vector<unsigned int> &rows_here;
    const double                     beta0;

    std::vector<double> gamma, beta, gap;
    std::vector<bool>   contact, contact_previous, solved_contact;
    std::vector<double> path_mu, path_alpha, w;
    std::vector<double> balanced, change, change_previous;
    double              norm_previous;
    double              eps_previous;
    double              eps_k;
    bool                first     = true;
    bool                beta_grew = false;
  };
} // namespace hrcontact

#endif
