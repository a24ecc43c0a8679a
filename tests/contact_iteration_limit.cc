// Reaching the iteration limit: the lift-off scene allowed only 2 multiplier
// updates. The run must exit with code 3 and a message naming the limit, and
// still write every result file, flagged converged = false. Then an initial
// penalty 1e16 times the nodal compliance (condensed path): alpha runs into
// Maximum penalty growth, the run stops with exit code 3 and a message naming
// the cause, files flagged converged = false, displacements still finite.

#include <filesystem>

#include "tests.h"

void
run(const std::string &name, const std::string &overrides)
{
  std::filesystem::remove_all("results");
  {
    std::ofstream prm("limited.prm");
    prm << "include " << SOURCE_DIR << "/../parameters/lift-off.prm\n"
        << overrides << "subsection Output\n  set Output directory = results\n"
        << "  set Print timing = false\nend\n";
  }
  std::ostringstream log, err;
  const int   code    = hrcontact::run_parameter_file("limited.prm", log, err);
  std::string message = err.str();
  // Keep the numbers out of the comparison: only their presence matters.
  message = message.substr(0, message.find("||pbar||"));
  std::cout << name << ": exit code " << code << "\n" << message << "\n";
  for (const std::string f :
       {"summary.txt", "contact.csv", "history.csv", "solution.vtu"})
    std::cout << "  " << f << " written: "
              << (std::filesystem::exists("results/" + f) ? "yes" : "NO")
              << "\n";
  const std::string summary = hrcontact_tests::read_file("results/summary.txt");
  std::cout << "  summary says converged = false: "
            << (summary.find("converged = false") != std::string::npos ? "yes" :
                                                                         "NO")
            << std::endl;
}

int
main()
{
  run("2 multiplier updates allowed",
      "subsection Augmented Lagrangian\n"
      "  set Maximum multiplier updates = 2\nend\n");
  const std::string summary = hrcontact_tests::read_file("results/summary.txt");
  std::cout << "  summary says iterations = 2: "
            << (summary.find("iterations = 2\n") != std::string::npos ? "yes" :
                                                                        "NO")
            << std::endl;
  run(
    "initial penalty 1e6 m/N",
    "subsection Augmented Lagrangian\n  set Initial penalty = 1e6\n  set Initial penalty scaling = absolute\nend\n"
    "subsection Equilibrium reduction\n  set Path = condensed\nend\n");
  const std::string s2    = hrcontact_tests::read_file("results/summary.txt");
  const auto        pos   = s2.find("max_abs_displacement_component = ");
  const double      u_max = std::stod(
    s2.substr(pos + std::string("max_abs_displacement_component = ").size()));
  std::cout << "  displacements finite and below 1 m: "
            << (std::isfinite(u_max) && u_max < 1 ? "yes" : "NO") << std::endl;
}
