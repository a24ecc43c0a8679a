// parameters/hertz.prm on a small mesh (3 refinements, 192 cells): contact
// half width and peak pressure within 5 % of Hertz, the solution converged,
// and the Signorini conditions hold.

#include "tests.h"

int
main()
{
  auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/hertz.prm") +
    "subsection Geometry\n  set Global refinements = 3\nend\n"
    "subsection Output\n  set Write solution = false\n  set Print timing = "
    "false\n  set Output directory = results\nend\n");
  std::ostringstream quiet;
  problem->output_results(quiet);
  const auto &s = problem->results().summary;
  std::cout << std::setprecision(4) << "cells " << s.get("cells")
            << ", converged = " << s.get("converged") << "\n"
            << "contact half width " << s.get_double("contact_half_width")
            << " m, Hertz " << s.get_double("hertz_half_width")
            << " m: within 5 %: "
            << hrcontact_tests::check(
                 std::abs(s.get_double("relative_error_half_width")), 0.05)
            << "\npeak pressure " << s.get_double("peak_pressure")
            << " Pa, Hertz " << s.get_double("hertz_peak_pressure")
            << " Pa: within 5 %: "
            << hrcontact_tests::check(
                 std::abs(s.get_double("relative_error_peak_pressure")), 0.05)
            << std::endl;
  hrcontact_tests::print_kkt(*problem);
}
