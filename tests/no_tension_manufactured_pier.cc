// The manufactured no-tension pier of parameters/no-tension-manufactured-
// pier.prm (issue 54), with the cone in closed form at the Gauss points: the
// top carries the closed form's own triangular traction (resultant N at
// e = b/4), so the exact stress is that triangle on every section, zero on
// the cracked strip x < b - c. At 4, 8 and 16 cells across: the iteration
// converges to its stress tolerance; the mid-height section carries N to
// round-off (DGQ1 on rectangles: the mid-line integral is the row average
// that discrete equilibrium fixes) and N e to O(h^2); the compressed width is c
// to within one cell; no Gauss point holds tension beyond the tolerance; and
// the L2 error of sigma_yy along the section falls with every refinement.

#include <deal.II/base/point.h>

#include <hrcontact/postprocess/field_values.h>
#include <hrcontact/postprocess/section_forces.h>

#include "tests.h"

using namespace hrcontact_tests;

int
main()
{
  std::cout << std::setprecision(3);
  const double      b = 1, e = 0.25, N = 1e5;
  const double      c = 3 * (b / 2 - e), q = 2 * N / c;
  const std::string pier =
    read_file(std::string(SOURCE_DIR) +
              "/../parameters/no-tension-manufactured-pier.prm");
  double previous = 1e300;
  for (const unsigned int r : {2u, 3u, 4u})
    {
      const auto problem = solve_from_text<2>(
        pier +
        "subsection Geometry\n  set Global refinements = " + std::to_string(r) +
        "\nend\nsubsection Output\n  set Write solution = false\n"
        "  set Output directory = results\nend\n");
      const auto        &res   = problem->results();
      const unsigned int cells = 1u << r;
      const double       h     = b / cells;
      std::cout << cells << " x " << 6 * cells
                << " cells: converged, in at most 150 Newton steps: "
                << (res.material.newton_steps <= 150 ? "yes" : "NO")
                << ", the last model stress change below 1e-6: "
                << check(res.material.changes.back(), 1e-6) << '\n';

      // The section through the middle of the cell row at mid-height.
      const double y0 = 3 + 0.5 * h;
      const auto   f  = horizontal_section(res, dealii::Point<2>(b / 2, y0));
      std::cout << "  section resultant = -N to 1e-9: "
                << check(std::abs(f.N + N) / N, 1e-9)
                << ", moment / (N e) = " << f.M / (N * e)
                << ", within h^2 / 10 of 1: "
                << check(std::abs(f.M / (N * e) - 1), 0.1 * h * h) << '\n';
      // sigma_yy along the section against the triangle.
      const unsigned int n     = 4000;
      double             width = 0, error = 0, norm = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double x = (i + 0.5) * b / n;
          const double s =
            hrcontact::point_value(res, dealii::Point<2>(x, y0), "syy");
          const double exact = (x > b - c) ? -q * (x - (b - c)) / c : 0.;
          error += (s - exact) * (s - exact);
          norm += exact * exact;
          if (s < -1e-3 * q)
            width += b / n;
        }
      error = std::sqrt(error / norm);
      std::cout << "  compressed width within one cell of c: "
                << check(std::abs(width - c), h)
                << ", tension at any Gauss point below the tolerance (1e-6 of "
                << "the largest stress): "
                << check(largest_gauss_point_stress(res), 1e-6)
                << "\n  L2 error of sigma_yy on the section " << error
                << ", below the coarser mesh's: "
                << (error < previous ? "yes" : "NO") << std::endl;
      previous = error;
    }

  // No compression, the mirror image: the top pulled by the same triangle,
  // the base held both ways (a membrane is not pushed by a foundation); the
  // exact stress is the triangle with the other sign, the strip x < b - c
  // wrinkled and stress-free.
  const std::string mirror =
    no_compression_mirror(pier, "Prescribed displacements = 2 x: 0");
  const auto problem = solve_from_text<2>(
    mirror + "subsection Geometry\n  set Global refinements = 3\nend\n"
             "subsection Output\n  set Write solution = false\n"
             "  set Output directory = results\nend\n");
  const auto  &res   = problem->results();
  const double y0    = 3 + 0.5 / 8;
  double       error = 0, norm = 0, width = 0;
  for (unsigned int i = 0; i < 4000; ++i)
    {
      const double x = (i + 0.5) * b / 4000;
      const double s =
        hrcontact::point_value(res, dealii::Point<2>(x, y0), "syy");
      const double exact = (x > b - c) ? q * (x - (b - c)) / c : 0.;
      error += (s - exact) * (s - exact);
      norm += exact * exact;
      if (s > 1e-3 * q)
        width += b / 4000;
    }
  std::cout << "No compression, the mirror at 8 x 48 cells: converged: "
            << check(res.material.changes.back(), 1e-6)
            << "\n  stretched width within one cell of c: "
            << check(std::abs(width - c), b / 8)
            << ", L2 error of sigma_yy on the section below 1 %: "
            << check(std::sqrt(error / norm), 1e-2) << std::endl;
}
