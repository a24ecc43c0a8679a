// The no-tension masonry arch (parameters/masonry-arch.prm at 192 cells,
// the interior point): the barrier path converges in at most 30 Newton
// steps (19 when written); no Gauss point carries tension beyond the
// allowance and the last stage's tolerance (the largest principal stress at
// most 1.01e-4 of the largest stress); the support reactions balance
// self-weight and load; the springings' contact pattern is printed.

#include "tests.h"

using namespace dealii;

int
main()
{
  const auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/masonry-arch.prm") +
    "subsection Geometry\n  set Global refinements = 2\nend\n"
    "subsection Output\n  set Write solution = false\n"
    "  set Output directory = results\nend\n");
  const auto &r   = problem->results();
  const auto &sys = r.system;
  std::cout << "converged: " << (r.converged() ? "yes" : "NO") << std::endl;

  std::cout << "in at most 30 Newton steps: "
            << (r.material.newton_steps <= 30 ? "yes" : "NO")
            << "\nno tension at any Gauss point (1.01e-4 of the largest "
               "stress): "
            << hrcontact_tests::check(
                 hrcontact_tests::largest_gauss_point_stress(r), 1.01e-4)
            << std::endl;

  double load = 0, reaction = 0;
  for (unsigned int i = 1; i < sys.n_displacement_dofs; i += 2)
    load += sys.load[i];
  auto add = [&](const hrcontact::EquilibriumRow &row, const double p) {
    reaction += hrcontact_tests::row_force(sys, row, p)[1];
  };
  unsigned int left_pressed = 0, left = 0, right_pressed = 0;
  double       right_pressed_x = 0;
  for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
    {
      const auto &row = sys.rows[sys.contact_rows[k]];
      add(row, r.reactions.contact[k]);
      const double x       = sys.node_coordinates[row.node][0];
      const bool   pressed = !r.contact->released[k];
      if (x < 0)
        {
          ++left;
          left_pressed += pressed;
        }
      else if (pressed)
        {
          ++right_pressed;
          right_pressed_x = x;
        }
    }
  for (unsigned int k = 0; k < sys.prescribed_rows.size(); ++k)
    add(sys.rows[sys.prescribed_rows[k]], r.reactions.support[k]);
  std::cout << "vertical load " << std::setprecision(6) << -load
            << ", support reactions balance it (1e-10): "
            << hrcontact_tests::check(std::abs(load + reaction) / -load, 1e-10)
            << "\nloaded springing: " << left_pressed << " of " << left
            << " nodes pressed\nfar springing: " << right_pressed
            << " node(s) pressed, at x = " << right_pressed_x << std::endl;
}
