// A semicircular no-tension arch under self-weight alone (issue 54):
// parameters/masonry-arch.prm without its point load, mean radius 4.7, at
// two thicknesses, with the cone in closed form at the Gauss points
// (96 cells along the axis). Limit analysis needs t/R >= 0.1075 (radial
// joints; a continuum with no tension in any direction cannot need less):
// at t/R = 0.18 the iteration must converge, with the reactions carrying
// the weight; at t/R = 0.09 it must stop with the named cause ("no admissible
// stress field", a NotConvergedError: exit code 3), in bounded steps. The
// same with the barrier path (Method = interior point), in at most 30 steps.

#include <hrcontact/core/input.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  std::string
  arch(const double t_over_R, const std::string &method)
  {
    const double R = 4.7, t = t_over_R * R;
    std::string  text =
      read_file(std::string(SOURCE_DIR) + "/../parameters/masonry-arch.prm");
    std::ostringstream radii, grid;
    radii << std::setprecision(17) << "Ri = " << R - t / 2
          << ", Ro = " << R + t / 2;
    grid << std::setprecision(17) << ": " << R - t / 2 << " : " << R + t / 2
         << " :";
    for (const auto &[from, to] :
         std::vector<std::pair<std::string, std::string>>{
           {"Ri = 4.1, Ro = 5", radii.str()},
           {": 4.1 : 5 :", grid.str()},
           {"P = 5e4", "P = 0"}})
      text.replace(text.find(from), from.size(), to);
    return text +
           "subsection Stress constraint iteration\n"
           "  set Method = " +
           method +
           "\nend\n"
           "subsection Material iteration\n  set Maximum steps = 200\nend\n"
           "subsection Output\n  set Write solution = false\n"
           "  set Output directory = results\nend\n";
  }
} // namespace

int
main()
{
  // The closed form to 1e-6, the barrier path (interior point) to 1e-4.
  for (const auto &[method, tolerance] :
       std::vector<std::pair<std::string, double>>{
         {"closed-form projection\n  set Stress tolerance = 1e-6", 1e-6},
         {"interior point\n  set Stress tolerance = 1e-4", 1e-4}})
    {
      if (tolerance > 1e-6)
        std::cout << "Method = interior point:" << std::endl;
      {
        const auto         problem = solve_from_text<2>(arch(0.18, method));
        const auto        &r       = problem->results();
        std::ostringstream quiet;
        problem->output_results(quiet);
        const double weight = -r.summary.get_double("total_load_y");
        std::cout << "t/R = 0.18: converged in at most "
                  << (tolerance > 1e-6 ? "30" : "150") << " Newton steps: "
                  << (r.material.newton_steps <= (tolerance > 1e-6 ? 30 : 150) ?
                        "yes" :
                        "NO")
                  << ", model stress error below "
                  << (tolerance > 1e-6 ? "1e-4" : "1e-6") << ": "
                  << check(r.material.changes.back(), tolerance)
                  << "\n  the reactions carry the weight to 1e-9: "
                  << check(std::abs(r.summary.get_double("total_reaction_y") -
                                    weight) /
                             weight,
                           1e-9)
                  << ", cracked area fraction " << std::setprecision(2)
                  << r.stress_constraint.cracked_fraction << std::endl;
      }
      try
        {
          solve_from_text<2>(arch(0.09, method));
          std::cout << "t/R = 0.09: NOT refused" << std::endl;
        }
      catch (const hrcontact::NotConvergedError &e)
        {
          const std::string what = e.what();
          std::cout << "t/R = 0.09: refused (exit code 3), naming the cause: "
                    << (what.find("no admissible stress field") !=
                            std::string::npos ?
                          "yes" :
                          "NO: " + what)
                    << std::endl;
        }
    }
}
