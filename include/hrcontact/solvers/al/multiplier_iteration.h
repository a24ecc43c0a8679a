#ifndef hrcontact_al_multiplier_iteration_h
#define hrcontact_al_multiplier_iteration_h

#include <deal.II/base/timer.h>

#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/al/stopping_tests.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <ostream>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * Steps 2-6 of section 4.4 after the trial solve, for the multiplier
   * updates of the consistent AL (eq. 28), the Macaulay AL (eq. 27) and the
   * pure penalty, in the classical scheme (inner Newton to eps_k, then one
   * update) or the diagonal one (one Newton step, then one update). One
   * object per solve; it works on the solver's ContactIteration and flags.
   */
  class MultiplierIteration
  {
  public:
    MultiplierIteration(AugmentedLagrangianSolver &solver,
                        const EquilibriumSystem   &system,
                        NewtonStepPath            &path,
                        const dealii::Timer       &timer,
                        const bool                 started,
                        std::ostream              &log);

    /** Iterate until a stopping test ends it (the solver's flags). */
    void
    run();

  private:
    /**
     * After a solve: the residuals, the branches at p, Step 4, the record,
     * Step 6 and the stopping tests, Step 5 and Step 2. False: stop.
     */
    bool
    after_solve();
    /** pbar of each row with the multipliers and compliances the solve
     * used; its norm. */
    double
    constraint_residuals();
    /** Each row's piece at p; the number of rows whose branch changed. */
    unsigned int
    read_pieces();
    /** Step 4: the multiplier update (eq. 48); the openings w_n - g. */
    void
    update_multipliers();
    /** Step 6: whether the iteration converged. */
    bool
    converged(const unsigned int update, const double norm) const;
    /** The diagonal scheme's periodicity test on this update. */
    bool
    periodic();
    /** Step 5: the penalty update (eq. 49); false when it hit its cap. */
    bool
    update_penalties(const unsigned int update,
                     const double       norm,
                     const unsigned int changes);
    /** Step 3: Newton steps until the gradient falls by eps_k. */
    void
    newton_steps(const unsigned int k);
    /** The pieces of the next Newton step and the gradient e in contact
     * coordinates; its norm. */
    double
    next_pieces(std::vector<ContactPiece> &active,
                std::vector<unsigned int> &branches) const;
    /** CG's tolerance tightened for the remaining solves, if it can be. */
    bool
    tighten(const std::string &symptom);

    AugmentedLagrangianSolver &solver;
    ContactIteration          &state;
    const EquilibriumSystem   &system;
    NewtonStepPath            &path;
    const ContactRowPartition &ownership;
    const dealii::Timer       &timer;
    const bool                 started;
    std::ostream              &log;
    const bool                 pure_penalty;
    const bool                 diagonal;
    const unsigned int         nq;
    /** The rows this process sees. */
    const std::vector<unsigned int> &rows_here;

    /** The piece each row had in the last Newton step, and the value of its
     * relation w - g there: the contact force term that solve balanced. */
    std::vector<ContactPiece> solved;
    std::vector<double>       balanced;
    std::vector<double>       pbar, pbar_previous;
    double                    norm_previous;
    double                    eps_previous;
    double                    eps_k;
    unsigned int              n_newton_steps   = 0;
    bool                      last_inner_exact = false;
    bool                      geometry_changed = false;
    /** The multipliers and compliances of the last solve, kept across an
     * update for the first Newton step after it. */
    std::vector<double> mu_solved, alpha_solved;
    bool                updated = false;
    PeriodicityTest     periodicity;
  };
} // namespace hrcontact

#endif
