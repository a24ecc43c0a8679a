// Poisson's ratio at the edges of plane strain (0, 0.49, 0.4999) on the
// lift-off scene, at 128 and 512 cells. Checked: the augmented Lagrangian
// converges, the reactions balance the load to 1e-8 and no reaction is
// tensile. Reported, not hidden: the settlement of the loaded corner at both
// meshes. Q1 displacements lock as nu -> 1/2 in plane strain (HR with DGQ1
// stresses equals Q1 on parallelograms), which shows as a settlement that
// still changes under refinement.

#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

int
main()
{
  const std::string base = hrcontact_tests::read_file(
    std::string(SOURCE_DIR) + "/../parameters/lift-off.prm");
  for (const double nu : {0., 0.49, 0.4999})
    {
      double settlement[2];
      for (unsigned int m = 0; m < 2; ++m)
        {
          std::ostringstream text;
          text << base
               << "set Constants = W = 2, H = 1, b = 0.5, q = 1e6, gamma = "
                  "24e3, E = 30e9, nu = "
               << nu
               << "\nsubsection Geometry\n  set Global refinements = " << 2 + m
               << "\nend\nsubsection Output\n  set Write solution = false\n"
                  "  set Print timing = false\n"
                  "  set Output directory = results\nend\n";
          auto problem = hrcontact_tests::solve_from_text<2>(text.str());
          std::ostringstream quiet;
          problem->output_results(quiet);
          const auto  &s         = problem->results().summary;
          const double imbalance = std::abs(s.get_double("total_load_y") +
                                            s.get_double("total_reaction_y")) /
                                   std::abs(s.get_double("total_load_y"));
          settlement[m] = -hrcontact::point_value(problem->results(),
                                                  dealii::Point<2>(2, 1),
                                                  "uy");
          std::cout << std::defaultfloat << std::setprecision(6)
                    << "nu = " << nu << ", " << s.get("cells")
                    << " cells: converged = " << s.get("converged")
                    << ", reactions balance the load (1e-8): "
                    << hrcontact_tests::check(imbalance, 1e-8)
                    << ", no tensile reaction: "
                    << hrcontact_tests::check(s.get_double("max_positive_p_n"),
                                              1e-6 *
                                                s.get_double("max_abs_p_n"))
                    << std::endl;
        }
      std::cout << "  settlement of the loaded corner: " << std::scientific
                << std::setprecision(4) << settlement[0] << " m, "
                << settlement[1] << " m (change under refinement " << std::fixed
                << std::setprecision(1)
                << 100 * (settlement[1] / settlement[0] - 1) << " %)"
                << std::defaultfloat << std::endl;
    }
}
