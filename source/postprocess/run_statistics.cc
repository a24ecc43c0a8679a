#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/postprocess/run_statistics.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  RunStatistics<dim>::execute(const Results<dim> &results,
                              PostprocessOutput  &output)
  {
    if (results.has_contact)
      output.summary.add("contact_solve_seconds",
                         results.contact_solve_seconds);
    // Peak resident memory, summed over the processes.
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    double peak = stats.VmHWM / 1024.;
    if (results.partition.distributed())
      peak = Utilities::MPI::sum(peak, results.partition.communicator);
    output.summary.add("peak_memory_MB", peak);
    output.summary.add("wall_time", results.wall_time);
  }

  template class RunStatistics<2>;
  template class RunStatistics<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    RunStatistics,
    "run statistics",
    40,
    "contact solve seconds, peak memory (summed over processes), wall time")
} // namespace hrcontact
