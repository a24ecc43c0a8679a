// The no-tension masonry pier of parameters/no-tension-pier.prm (issue 18):
// 1 m wide, 6 m tall, on a unilateral foundation, the load N = 1e5 N/m on a
// strip of the top at e = b/4 from the axis (beyond the middle third). At
// 4 x 24 and 8 x 48 cells: the augmented Lagrangian of the cone converges
// (residual below 1e-10); the KKT conditions of the foundation hold; the
// section through the middle of the cell row at mid-height carries N to
// round-off (for DGQ1 on rectangles the mid-line integral of sigma_yy is
// the row average that discrete equilibrium fixes); and its moment, the
// compressed width and the peak stress are printed against the closed form
// of a no-tension rectangle (c = 3 (b/2 - e) = 0.75 m, sigma_max = 2N/c),
// with the tension the cell-centre cone leaves between the centres on that
// line (it falls like h: doc/materials.md).
// The scene imposes the cone at the cell centres (see its comments); the
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
  for (const unsigned int r : {2u, 3u})
    {
      const auto problem = solve_from_text<2>(
        pier +
        "subsection Geometry\n  set Global refinements = " + std::to_string(r) +
        "\nend\nsubsection Equilibrium reduction\n  set Path = condensed\n"
        "end\nsubsection Output\n  set Write solution = false\n"
        "  set Output directory = results\nend\n");
      std::ostringstream quiet;
      problem->output_results(quiet); // the balance report for print_kkt
      const auto &res = problem->results();
      std::cout << (4 << r) / 4 << " x " << 6 * (1 << r)
                << " cells: converged in at most 20 updates: "
                << (res.stress_constraint.residuals.size() <= 20 ? "yes" : "NO")
                << ", last residual < 1e-10: "
                << check(res.stress_constraint.residuals.back(), 1e-10) << '\n';
      print_kkt(*problem);

      // The section through the middle of the cell row at mid-height.
      const double y0 = 3 + 0.5 / (1 << r);
      const auto   f  = horizontal_section(res, dealii::Point<2>(b / 2, y0));
      std::cout << "  section resultant = -N to 1e-10: "
                << check(std::abs(f.N + N) / N, 1e-10)
                << "\n  section moment / (N e) = " << -f.M / (N * e)
                << std::endl;
      // The compressed width and the peak along the same line.
      const unsigned int n      = 4000;
      double             width  = 0;
      double             s_peak = 0, s_tension = 0, tension = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double s =
            hrcontact::point_value(res,
                                   dealii::Point<2>((i + 0.5) * b / n, y0),
                                   "syy");
          s_peak    = std::min(s_peak, s);
          s_tension = std::max(s_tension, s);
          tension += std::max(s, 0.) * b / n;
          if (s < -1e-3 * peak)
            width += b / n;
        }
      std::cout << "  compressed width / 3 (b/2 - e) = " << width / c
                << ", peak stress / (2N/c) = " << -s_peak / peak
                << ", cracked area fraction "
                << res.stress_constraint.cracked_fraction
                << "\n  tension the cell-centre cone leaves on the line: "
                << "largest / (2N/c) = " << s_tension / peak
                << ", resultant / N = " << tension / N
                << "\n  displacement probes in a cracked region: top left "
                << res.summary.get("probe_in_cracked_region.top_left")
                << ", top right "
                << res.summary.get("probe_in_cracked_region.top_right")
                << std::endl;
    }
}
