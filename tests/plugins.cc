// The extension points by name: Postprocess/List of postprocessors runs the
// named postprocessors in order (a name that does not apply is skipped with
// a note, an unknown one is an error naming the known ones), and
// Material/Model picks a registered material law. A run lists only what it
// wrote.

#include <hrcontact/postprocess/postprocessor.h>

#include <filesystem>

#include "tests.h"

namespace
{
  std::string
  block(const std::string &extra)
  {
    return hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                      "/../parameters/block.prm") +
           "subsection Output\n  set Output directory = results-list\n"
           "  set Print timing = false\nend\n" +
           extra;
  }

  std::string
  files_in(const std::string &directory)
  {
    std::vector<std::string> names;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string list;
    for (const auto &n : names)
      list += (list.empty() ? "" : ", ") + n;
    return list;
  }

  void
  expect_error(const std::string &title, const std::string &text)
  {
    try
      {
        hrcontact_tests::solve_from_text<2>(text);
        std::cout << title << ": NO error" << std::endl;
      }
    catch (const hrcontact::InputError &e)
      {
        std::cout << title << ": " << e.what() << std::endl;
      }
  }
} // namespace

int
main()
{
  std::cout << "registered postprocessors (the order of 'all'):";
  for (const auto &name :
       hrcontact::PostprocessorManager<2>::registered_names())
    std::cout << " '" << name << "'";
  std::cout << std::endl;

  {
    const std::string text =
      block("subsection Postprocess\n  set List of postprocessors = contact "
            "tables, balance\nend\n");
    std::filesystem::remove_all("results-list");
    auto               problem = hrcontact_tests::solve_from_text<2>(text);
    std::ostringstream log;
    problem->output_results(log);
    const auto &summary = problem->results().summary;
    bool        probes  = false;
    for (const auto &[key, value] : summary.entries)
      probes |= (key.rfind("probe.", 0) == 0);
    std::cout
      << "block, list 'contact tables, balance':\n  log notes: "
      << (log.str().find("postprocessor 'contact tables' skipped: "
                         "the scene has no contact") != std::string::npos ?
            "contact tables skipped (no contact)" :
            "NO note")
      << "\n  balance ran, imbalance < 1e-10: "
      << hrcontact_tests::check(summary.get_double("equilibrium_imbalance"),
                                1e-10)
      << "\n  probes ran: " << (probes ? "YES" : "no")
      << "\n  files written: " << files_in("results-list") << std::endl;
  }

  expect_error("unknown postprocessor",
               block("subsection Postprocess\n  set List of postprocessors "
                     "= balance, hertz\nend\n"));
  expect_error("listed twice",
               block("subsection Postprocess\n  set List of postprocessors "
                     "= balance, balance\nend\n"));
  expect_error("unknown material law",
               block("subsection Material\n  set Model = no tension\nend\n"));
}
