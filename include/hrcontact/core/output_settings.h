#ifndef hrcontact_output_settings_h
#define hrcontact_output_settings_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace hrcontact
{
  /** Where results go and how chatty a run is (subsection Output). */
  struct OutputSettings
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    std::string directory    = "output";
    bool        print_timing = true;
    /** Benchmarks: time one linear elastic solve (see declare_parameters). */
    bool time_linear_solve = false;
    /** Benchmarks: time the plain Q1 displacement solve of the same mesh. */
    bool time_floor = false;
    /** Benchmarks: solve a nonlinear law once more the displacement way
     * (DisplacementLawStiffness; see declare_parameters). */
    bool compare_displacement_code = false;
  };
} // namespace hrcontact

#endif
