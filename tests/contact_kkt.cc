// KKT conditions of the converged lift-off scene (parameters/lift-off.prm):
// equilibrium, compressive reactions, no penetration, complementarity, total
// reaction = applied load, and part of the base lifted off.

#include "tests.h"

void
run(const std::string &name, const std::string &extra)
{
  auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/lift-off.prm") +
    extra +
    "subsection Output\n  set Write solution = false\n  set Print timing = "
    "false\n  set Output directory = results\nend\n");
  std::ostringstream quiet;
  problem->output_results(quiet);
  std::cout << name
            << ": converged = " << problem->results().summary.get("converged")
            << ", total load y = "
            << problem->results().summary.get("total_load_y")
            << ", total reaction y = "
            << problem->results().summary.get("total_reaction_y") << std::endl;
  hrcontact_tests::print_kkt(*problem);
}

int
main()
{
  run("lift-off, global penalty update", "");
  run("lift-off, per-constraint penalty update",
      "subsection Augmented Lagrangian\n  set Penalty update = per "
      "constraint\nend\n");
}
