// The no-tension masonry pier of parameters/no-tension-pier.prm (issue 18,
// issue 54): 1 m wide, 6 m tall, on a unilateral foundation, the load N =
// 1e5 N/m on a strip of the top at e = b/4 from the axis (beyond the middle
// third), the cone at every Gauss point by the interior point. At 8 x 48
// cells: the barrier path converges (model stress change below the scene's
// 1e-6, which fixes the section's peak: at 1e-4 it moved by 3-6 % with the
// path) in at most 1000 Newton steps (698 when written); no Gauss point
// carries tension beyond the allowance and the tolerance; the KKT conditions
// of the foundation hold; the section through the middle of the cell row at
// mid-height carries N to round-off (for DGQ1 on rectangles the mid-line
// integral of sigma_yy is the row average that discrete equilibrium fixes);
// its moment, compressed width and peak are printed against the closed form
// of a no-tension rectangle (c = 3 (b/2 - e) = 0.75 m, sigma_max = 2N/c),
// which this load does not reach (doc/materials.md), and so is the share of
// N the outer sixteenth of the section (x > 15/16 b) carries. The
// displacement probes at the top corners say whether they lie in a cracked
// region.

#include <deal.II/base/point.h>

#include <hrcontact/postprocess/field_values.h>
#include <hrcontact/postprocess/section_forces.h>

#include "tests.h"

using namespace hrcontact_tests;

int
main()
{
  std::cout << std::setprecision(4);
  const double      b = 1, e = 0.25, N = 1e5;
  const double      c = 3 * (b / 2 - e), peak = 2 * N / c;
  const std::string pier =
    read_file(std::string(SOURCE_DIR) + "/../parameters/no-tension-pier.prm");
  const unsigned int r       = 3;
  const auto         problem = solve_from_text<2>(
    pier + "subsection Output\n  set Write solution = false\n"
                   "  set Output directory = results\nend\n");
  std::ostringstream quiet;
  problem->output_results(quiet); // the balance report for print_kkt
  const auto &res = problem->results();
  std::cout << (4 << r) / 4 << " x " << 6 * (1 << r)
            << " cells: converged (model stress change below 1e-6): "
            << check(res.material.changes.back(), 1e-6)
            << ", in at most 1000 Newton steps: "
            << (res.material.newton_steps <= 1000 ? "yes" : "NO")
            << "\n  tension at any Gauss point below 2.01e-6 of the largest "
               "stress (the allowance and the tolerance): "
            << check(largest_gauss_point_stress(res), 2.01e-6) << '\n';
  print_kkt(*problem);

  // The section through the middle of the cell row at mid-height.
  const double y0 = 3 + 0.5 / (1 << r);
  const auto   f  = horizontal_section(res, dealii::Point<2>(b / 2, y0));
  std::cout << "  section resultant = -N to 1e-10: "
            << check(std::abs(f.N + N) / N, 1e-10)
            << "\n  section moment / (N e) = " << -f.M / (N * e) << std::endl;
  // The compressed width, the peak and its place along the same line.
  const unsigned int n     = 4000;
  double             width = 0, s_peak = 0, x_peak = 0, outer = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      const double x = (i + 0.5) * b / n;
      const double s =
        hrcontact::point_value(res, dealii::Point<2>(x, y0), "syy");
      if (s < s_peak)
        s_peak = s, x_peak = x;
      if (s < -1e-3 * peak)
        width += b / n;
      if (x > 15. / 16 * b)
        outer -= s * b / n;
    }
  std::cout << "  compressed width / 3 (b/2 - e) = " << width / c
            << ", peak stress / (2N/c) = " << -s_peak / peak
            << " at x / b = " << x_peak / b
            << "\n  share of N on x > 15/16 b: " << outer / N
            << ", cracked area fraction "
            << res.stress_constraint.cracked_fraction
            << "\n  displacement probes in a cracked region: top left "
            << res.summary.get("probe_in_cracked_region.top_left")
            << ", top right "
            << res.summary.get("probe_in_cracked_region.top_right")
            << std::endl;
}
