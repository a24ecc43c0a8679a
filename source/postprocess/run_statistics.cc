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
    if (results.displacement_code_steps > 0)
      {
        output.summary.add("displacement_code_newton_steps",
                           results.displacement_code_steps);
        output.summary.add("displacement_code_local_steps",
                           results.displacement_code_local_steps);
        output.summary.add("displacement_code_seconds",
                           results.displacement_code_seconds);
        output.summary.add("stress_code_seconds",
                           results.contact_solve_seconds);
        output.summary.add("displacement_code_to_solve",
                           results.displacement_code_seconds /
                             results.contact_solve_seconds);
        output.summary.add("displacement_code_difference",
                           results.displacement_code_difference);
      }
    if (results.floor_displacement.size() > 0)
      {
        output.summary.add("q1_floor_seconds", results.floor_seconds);
        output.summary.add("q1_floor_cg_iterations", results.floor_iterations);
        output.summary.add("contact_solve_to_floor",
                           results.contact_solve_seconds /
                             results.floor_seconds);
        if (results.linear_elastic_seconds > 0)
          output.summary.add("elastic_solve_to_floor",
                             results.linear_elastic_seconds /
                               results.floor_seconds);
      }
  }

  template class RunStatistics<2>;
  template class RunStatistics<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    RunStatistics,
    "run statistics",
    40,
    "contact solve seconds, peak memory (summed over processes), wall time")
} // namespace hrcontact
