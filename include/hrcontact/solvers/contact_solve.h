#ifndef hrcontact_contact_solve_h
#define hrcontact_contact_solve_h

#include <deal.II/base/timer.h>

#include <hrcontact/core/results.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/material_loop.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <ostream>
#include <vector>

namespace hrcontact
{
  /**
   * The solve on a Newton-step path: the augmented Lagrangian of the
   * contact rows (or the one solve without contact, after checking that
   * supports hold every rigid motion), inside the material loop. Each
   * material Newton step is a whole contact solve started from the last
   * step's multipliers, penalties and reactions.
   */
  template <int dim>
  class ContactSolve
  {
  public:
    ContactSolve(AugmentedLagrangianSolver &contact_solver,
                 MaterialLoop<dim>         &material_loop);

    /** Solve on `path`; results gets contact, contact_w and
     * free_rigid_motions (and the material loop's figures). */
    void
    run(EquilibriumSystem   &system,
        NewtonStepPath      &path,
        Results<dim>        &results,
        dealii::TimerOutput &timer,
        std::ostream        &log);

  private:
    /** Without contact: one solve (a material loop of them). */
    void
    run_without_contact(EquilibriumSystem &system,
                        NewtonStepPath    &path,
                        Results<dim>      &results,
                        std::ostream      &log);

    /**
     * The bodies only contact holds along some rigid motion, each with the
     * contact rows at its nodes (a pair row at both bodies'), for the
     * augmented Lagrangian's floating-body test; their motions' count.
     */
    unsigned int
    find_bodies_held_only_by_contact(const EquilibriumSystem &system);

    AugmentedLagrangianSolver &contact_solver;
    MaterialLoop<dim>         &material_loop;
  };
} // namespace hrcontact

#endif
