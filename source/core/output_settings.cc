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
                      "Print a table of wall times at the end of the run, "
                      "and the resident memory of the largest process after "
                      "each stage (tests switch it off to keep their output "
                      "reproducible).");
    prm.leave_subsection();
  }

  void
  OutputSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory    = prm.get("Output directory");
    print_timing = prm.get_bool("Print timing");
    prm.leave_subsection();
  }
} // namespace hrcontact
