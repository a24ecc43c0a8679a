#ifndef hrcontact_q1_floor_h
#define hrcontact_q1_floor_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/results.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <ostream>

namespace hrcontact
{
  /**
   * Output/Time the Q1 floor: the plain Q1 displacement solve of the same
   * mesh, processes and supports (every contact row held at its gap), its
   * stiffness from the displacement bilinear form, CG and the same AMG and
   * tolerance. Every performance figure of doc/benchmarks.md is a ratio to
   * it.
   */
  template <int dim>
  class Q1Floor
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Time it (assembly to solution) into results: floor_seconds,
     * floor_iterations and floor_displacement. Nothing unless asked for;
     * whether it ran. */
    bool
    run(const LinearSolverSettings &linear_solver,
        const bool                  print_timing,
        Results<dim>               &results,
        std::ostream               &log) const;

    bool enabled = false;
  };
} // namespace hrcontact

#endif
