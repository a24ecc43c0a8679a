// Reaching the iteration limit: the lift-off scene allowed only 2 multiplier
// updates. The run must exit with code 3 and a message naming the limit, and
// still write every result file, flagged converged = false.

#include <filesystem>

#include "tests.h"

int
main()
{
  std::filesystem::remove_all("results");
  {
    std::ofstream prm("limited.prm");
    prm << "include " << SOURCE_DIR << "/../parameters/lift-off.prm\n"
        << "subsection Augmented Lagrangian\n"
        << "  set Maximum multiplier updates = 2\nend\n"
        << "subsection Output\n  set Output directory = results\n"
        << "  set Print timing = false\nend\n";
  }
  std::ostringstream log, err;
  const int   code    = hrcontact::run_parameter_file("limited.prm", log, err);
  std::string message = err.str();
  // Keep the numbers out of the comparison: only their presence matters.
  message = message.substr(0, message.find("||pbar||"));
  std::cout << "exit code " << code << "\n" << message << "\n";
  for (const std::string f :
       {"summary.txt", "contact.csv", "history.csv", "solution.vtu"})
    std::cout << f << " written: "
              << (std::filesystem::exists("results/" + f) ? "yes" : "NO")
              << "\n";
  const std::string summary = hrcontact_tests::read_file("results/summary.txt");
  std::cout << "summary says converged = false: "
            << (summary.find("converged = false") != std::string::npos ? "yes" :
                                                                         "NO")
            << "\nsummary says iterations = 2: "
            << (summary.find("iterations = 2\n") != std::string::npos ? "yes" :
                                                                        "NO")
            << std::endl;
}
