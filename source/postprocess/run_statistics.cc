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
      output.summary.add("contact_solve_seconds", results.solve.seconds);
    // Peak resident memory, summed over the processes.
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    double peak = stats.VmHWM / 1024.;
    if (results.partition.distributed())
      peak = Utilities::MPI::sum(peak, results.partition.communicator);
    output.summary.add("peak_memory_MB", peak);
    output.summary.add("wall_time", results.wall_time);
    if (results.diagnostics.displacement_code_steps > 0)
      {
        output.summary.add("displacement_code_newton_steps",
                           results.diagnostics.displacement_code_steps);
        output.summary.add("displacement_code_local_steps",
                           results.diagnostics.displacement_code_local_steps);
        output.summary.add("displacement_code_seconds",
                           results.diagnostics.displacement_code_seconds);
        output.summary.add("stress_code_seconds", results.solve.seconds);
        output.summary.add("displacement_code_to_solve",
                           results.diagnostics.displacement_code_seconds /
                             results.solve.seconds);
        output.summary.add("displacement_code_difference",
                           results.diagnostics.displacement_code_difference);
      }
    if (results.diagnostics.floor_displacement.size() > 0)
      {
        output.summary.add("q1_floor_seconds",
                           results.diagnostics.floor_seconds);
        output.summary.add("q1_floor_cg_iterations",
                           results.diagnostics.floor_iterations);
        output.summary.add("contact_solve_to_floor",
                           results.solve.seconds /
                             results.diagnostics.floor_seconds);
        if (results.diagnostics.linear_elastic_seconds > 0)
          output.summary.add("elastic_solve_to_floor",
                             results.diagnostics.linear_elastic_seconds /
                               results.diagnostics.floor_seconds);
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
