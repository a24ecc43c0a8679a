// Mesh convergence of parameters/cantilever.prm (plane stress, end shear,
// Timoshenko-Goodier clamp) towards beam theory and the elasticity solution:
// tip deflection, root stress at the top fibre, relative L2 stress error and
// its observed order, with DGQ1 stresses (= Q1 displacements) and with the
// scene's Pian-Sumihara stresses. Errors must fall at every refinement.

#include <cmath>

#include "tests.h"

namespace
{
  void
  convergence(const std::string &element)
  {
    const std::string base =
      hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                 "/../parameters/cantilever.prm") +
      "subsection Finite elements\n  set Stress element = " + element +
      "\nend\n";
    std::cout << element << ":\n"
              << "cells   tip/beam    root/beam   L2 stress error   order"
              << std::endl;
    double previous_error = 0, previous_tip = 1, previous_root = 1;
    bool   monotone = true;
    for (unsigned int r = 0; r < 4; ++r)
      {
        auto problem = hrcontact_tests::solve_from_text<2>(
          base + "subsection Geometry\n  set Global refinements = " +
          std::to_string(r) +
          "\nend\nsubsection Output\n  set Write solution = false\n"
          "  set Output directory = results\nend\n");
        std::ostringstream quiet;
        problem->output_results(quiet);
        const hrcontact::Summary &summary = problem->results().summary;
        const double tip = summary.get_double("probe.tip_deflection") /
                           summary.get_double("reference.tip_deflection");
        const double root = summary.get_double("probe.root_stress") /
                            summary.get_double("reference.root_stress");
        const double err = summary.get_double("stress_error_l2");
        std::cout << std::setw(5)
                  << problem->results().triangulation().n_active_cells()
                  << std::fixed << std::setprecision(5) << std::setw(11) << tip
                  << std::setw(12) << root << std::setw(14)
                  << std::setprecision(5) << err;
        if (r > 0)
          std::cout << std::setw(12) << std::setprecision(2)
                    << std::log2(previous_error / err);
        std::cout << std::endl;
        if (r > 0)
          monotone &= (err < previous_error) &&
                      (std::abs(1 - tip) < std::abs(1 - previous_tip)) &&
                      (std::abs(1 - root) < std::abs(1 - previous_root));
        previous_error = err;
        previous_tip   = tip;
        previous_root  = root;
      }
    std::cout << "errors decrease at every refinement: "
              << (monotone ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main()
{
  for (const std::string element : {"DGQ1", "Pian-Sumihara"})
    convergence(element);
}
