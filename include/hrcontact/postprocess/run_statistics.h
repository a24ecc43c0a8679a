#ifndef hrcontact_run_statistics_h
#define hrcontact_run_statistics_h

#include <hrcontact/postprocess/postprocessor.h>

namespace hrcontact
{
  /**
   * Postprocessor "run statistics": contact_solve_seconds (with contact),
   * peak_memory_MB (summed over the processes) and wall_time, the figures
   * doc/benchmarks.md quotes.
   */
  template <int dim>
  class RunStatistics : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}
    void
    execute(const Results<dim> &results, PostprocessOutput &output) override;
  };
} // namespace hrcontact

#endif
