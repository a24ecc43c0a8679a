#ifndef hrcontact_displacement_code_comparison_h
#define hrcontact_displacement_code_comparison_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/results.h>
#include <hrcontact/solvers/linear_solver_settings.h>
#include <hrcontact/solvers/material_iteration.h>

#include <ostream>

namespace hrcontact
{
  /**
   * Output/Compare with a displacement code: a nonlinear law solved once
   * more the way a displacement code must (DisplacementLawStiffness: Newton
   * on the Q1 displacements, the law inverted at every Gauss point and
   * step), on the run's supports, processes and linear solver, after the
   * run's own solve (doc/materials.md).
   */
  template <int dim>
  class DisplacementCodeComparison
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Refuse, before any solve, a scene it cannot compare: a linear law,
     * contact or a stress constraint. */
    void
    check_scene(const Scene<dim> &scene, const bool has_contact) const;

    /** Solve it and record its steps, time and difference in results
     * (displacement_code_*). Nothing unless asked for. */
    void
    run(const MaterialIteration    &material_iteration,
        const LinearSolverSettings &linear_solver,
        Results<dim>               &results,
        std::ostream               &log) const;

    bool enabled = false;
  };
} // namespace hrcontact

#endif
