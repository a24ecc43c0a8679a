#include <hrcontact/core/output_settings.h>

namespace hrcontact
{
  using namespace dealii;

  void
  OutputSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::Anything(),
                      "Directory for summary.txt and solution.vtu, relative "
                      "to the working directory; created if missing.");
    prm.declare_entry("Print timing",
                      "true",
                      Patterns::Bool(),
                      "Print a table of wall times at the end of the run "
                      "(tests switch it off to keep their output "
                      "reproducible).");
    prm.declare_entry(
      "Time a linear elastic solve",
      "false",
      Patterns::Bool(),
      "Benchmarks: before the contact iteration, solve the condensed system "
      "once more with every contact row held at its gap (a linear elastic "
      "problem on the same mesh and processes, from a fresh matrix and "
      "preconditioner) and report its wall time as "
      "linear_elastic_solve_seconds beside contact_solve_seconds in "
      "summary.txt. Condensed path only; costs one extra solve.");
    prm.leave_subsection();
  }

  void
  OutputSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory         = prm.get("Output directory");
    print_timing      = prm.get_bool("Print timing");
    time_linear_solve = prm.get_bool("Time a linear elastic solve");
    prm.leave_subsection();
  }
} // namespace hrcontact
