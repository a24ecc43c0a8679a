#ifndef hrcontact_output_settings_h
#define hrcontact_output_settings_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace hrcontact
{
  /** Where results go and how chatty a run is (subsection Output; the
   * benchmark entries there belong to the classes of diagnostics/). */
  struct OutputSettings
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    std::string directory    = "output";
    bool        print_timing = true;
  };
} // namespace hrcontact

#endif
