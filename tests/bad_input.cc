// Bad input ends with one clear message naming the cause, a non-zero exit
// code and no result file. Runs what the executable runs on each file of
// tests/input/ and prints the exit code and the message (the expected
// output); the CTest entries cli/exit-code-* check the real executable.

#include <filesystem>

#include "tests.h"

int
main()
{
  const std::string dir = std::string(SOURCE_DIR) + "/input/";
  for (const std::string name : {"unknown-entry",
                                 "malformed-expression",
                                 "wrong-component-count",
                                 "floating-body",
                                 "floating-body-condensed",
                                 "floating-on-foundation",
                                 "floating-on-foundation-3d",
                                 "poor-stress-space",
                                 "impossible-geometry",
                                 "conflicting-supports",
                                 "incompressible",
                                 "impossible-tunnel",
                                 "support-and-constraint",
                                 "displacement-al-null-space",
                                 "nested-too-deep",
                                 "nested-malformed",
                                 "refinement-region-malformed",
                                 "refinement-region-missing",
                                 "refinement-null-space",
                                 "adaptive-fraction",
                                 "adaptive-fractions-sum",
                                 "adaptive-estimator",
                                 "adaptive-bound-contact",
                                 "adaptive-target-error",
                                 "adaptive-null-space",
                                 "bodies-overlap",
                                 "pair-out-of-reach",
                                 "traction-missing-id",
                                 "obstacle-missing-id",
                                 "support-missing-id",
                                 "normal-displacement-missing-id",
                                 "boundary-support-missing-id",
                                 "stop-missing-id",
                                 "pair-missing-id",
                                 "pair-law-missing-id",
                                 "probe-outside",
                                 "no-such-file"})
    {
      std::filesystem::remove_all("should-not-exist");
      std::ostringstream log, err;
      const int          code =
        hrcontact::run_parameter_file(dir + name + ".prm", log, err);
      std::string message = err.str();
      for (std::size_t p; (p = message.find(dir)) != std::string::npos;)
        message.replace(p, dir.size(), "<tests>/input/");
      std::cout << name << ": exit code " << code << "\n  " << message
                << "  result files written: "
                << (std::filesystem::exists("should-not-exist") ? "YES" : "no")
                << std::endl;
    }
  // The manufactured no-tension pier without its horizontal guide: it used
  // to take 300 material steps and stop as not converged.
  hrcontact_tests::print_input_refusal(
    "no-tension pier without its horizontal guide",
    hrcontact_tests::scene_at_refinement("no-tension-manufactured-pier", 2, 2) +
      "subsection Supports\n  set Prescribed displacements =\nend\n");
  // The point-load pier at 16 cells across with a residual stiffness too
  // small to hold its cracked strip: the singular stiffness is named as
  // such, with the entry that holds it.
  hrcontact_tests::print_input_refusal(
    "no-tension pier with too small a residual stiffness",
    hrcontact_tests::scene_at_refinement("no-tension-pier", 3, 4) +
      "subsection Stress constraint iteration\n"
      "  set Barrier residual stiffness = 1e-10\nend\n");
}
