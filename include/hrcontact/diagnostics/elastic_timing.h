#ifndef hrcontact_elastic_timing_h
#define hrcontact_elastic_timing_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/results.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <ostream>

namespace hrcontact
{
  /**
   * Output/Time a linear elastic solve: the condensed system solved once
   * more with every contact row held at its gap, from a fresh matrix and
   * preconditioner, beside the contact solve (condensed path only).
   */
  template <int dim>
  class ElasticTiming
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Time it into results.linear_elastic_seconds (zero when not asked
     * for or not on the condensed path); whether it ran. */
    bool
    run(const LinearSolverSettings &linear_solver,
        Results<dim>               &results,
        std::ostream               &log) const;

    bool enabled = false;
  };
} // namespace hrcontact

#endif
