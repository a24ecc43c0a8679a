// Hertz between two deformable bodies (issue 19): parameters/two-cylinders.prm,
// a steel cylinder (R1 = 0.05) on an aluminium one (R2 = 0.1), plane strain,
// non-matching graded meshes, node to segment and mortar. Against Hertz with
// 1/R* = 1/R1 + 1/R2 and 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2: the
// refinement table of the half width and the peak pressure (nodal reaction
// over the tributary length), both paths... the condensed one (the dense
// reduction would need gigabytes); on the finest mesh the peak pressure
// within 2 % and the half width within one slave node spacing. Also: every
// pair row's slave and master reactions sum to zero, and the loads balance
// the reactions.

#include <deal.II/base/numbers.h>

#include <algorithm>

#include "tests.h"

int
main()
{
  const std::string scene = hrcontact_tests::read_file(
    std::string(SOURCE_DIR) + "/../parameters/two-cylinders.prm");
  const double R1 = 0.05, R2 = 0.1, E1 = 210e9, E2 = 70e9, nu = 0.3;
  const double Rs      = 1 / (1 / R1 + 1 / R2);
  const double Es      = 1 / ((1 - nu * nu) / E1 + (1 - nu * nu) / E2);
  const double a_hertz = 0.1 * R1;
  const double P = dealii::numbers::PI * Es * a_hertz * a_hertz / (4 * Rs);
  const double p_hertz = 2 * P / (dealii::numbers::PI * a_hertz);

  for (const std::string method : {"node to segment", "mortar"})
    for (const unsigned int refinements : {3u, 4u, 5u})
      {
        if (refinements == 3)
          std::cout << method
                    << ": refinements, cells, pair rows, updates, half width / "
                       "a - 1, peak / p0 - 1, node spacing at x = a / a\n";
        const auto problem = hrcontact_tests::solve_from_text<2>(
          scene + "subsection Geometry\n  set Global refinements = " +
          std::to_string(refinements) +
          "\nend\nsubsection Contact\n  set Pair method = " + method +
          "\nend\nsubsection Output\n  set Write solution = false\n"
          "  set Output directory = results\nend\n");
        const auto &r   = problem->results();
        const auto &sys = r.system;
        // The slave rows by x: the pressed zone, its pressures and the node
        // spacing there.
        std::vector<std::tuple<double, double, bool>> rows; // x, p, pressed
        double pair_sum = 0, total[2] = {0, 0}, largest = 0;
        for (unsigned int i = 0; i < sys.n_displacement_dofs; ++i)
          total[i % 2] += sys.load[i];
        auto add = [&](const hrcontact::EquilibriumRow &row, const double p) {
          const auto sum = hrcontact_tests::row_force(sys, row, p);
          total[0] += sum[0];
          total[1] += sum[1];
          largest = std::max(largest, std::abs(p));
          return std::max(std::abs(sum[0]), std::abs(sum[1]));
        };
        for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
          {
            const auto  &row = sys.rows[sys.contact_rows[k]];
            const double p   = r.reactions.contact[k];
            pair_sum =
              std::max(pair_sum, add(row, p) / std::max(std::abs(p), 1e-300));
            rows.emplace_back(sys.node_coordinates[row.node][0],
                              p,
                              !r.contact->released[k]);
          }
        for (unsigned int k = 0; k < sys.prescribed_rows.size(); ++k)
          add(sys.rows[sys.prescribed_rows[k]], r.reactions.support[k]);
        std::sort(rows.begin(), rows.end());
        // Pressure: the nodal reaction over its tributary length along x
        // (half a spacing at the symmetry plane).
        double peak = 0, zone_end = 0, spacing = 0;
        for (unsigned int j = 0; j < rows.size(); ++j)
          {
            const double x    = std::get<0>(rows[j]);
            const double left = j > 0 ? std::get<0>(rows[j - 1]) : x;
            const double right =
              j + 1 < rows.size() ? std::get<0>(rows[j + 1]) : x;
            const double length = 0.5 * (right - left);
            if (std::get<2>(rows[j]))
              {
                peak     = std::max(peak, -std::get<1>(rows[j]) / length);
                zone_end = x + 0.5 * (right - x);
              }
            if (left <= a_hertz && x >= a_hertz)
              spacing = x - left;
          }
        const double width_error = zone_end / a_hertz - 1;
        const double peak_error  = peak / p_hertz - 1;
        std::cout << refinements << ", " << r.triangulation().n_active_cells()
                  << ", " << rows.size() << ", " << r.contact->history.size()
                  << std::fixed << std::setprecision(4) << ", " << width_error
                  << ", " << peak_error << ", " << spacing / a_hertz
                  << std::defaultfloat << std::endl;
        std::cout << "  pair reactions sum to zero (1e-12 |p|): "
                  << hrcontact_tests::check(pair_sum, 1e-12)
                  << ", balance (1e-10): "
                  << hrcontact_tests::check(std::max(std::abs(total[0]),
                                                     std::abs(total[1])) /
                                              largest,
                                            1e-10)
                  << std::endl;
        if (refinements == 5)
          std::cout << "  finest: peak pressure within 2 %: "
                    << hrcontact_tests::check(std::abs(peak_error), 0.02)
                    << "\n  half width within one node spacing: "
                    << hrcontact_tests::check(std::abs(zone_end - a_hertz),
                                              spacing)
                    << std::endl;
        if (refinements == 5 && method == "mortar")
          std::cout << "  mortar: peak pressure within 0.5 % (node to segment "
                       "settles near +0.5 %): "
                    << hrcontact_tests::check(std::abs(peak_error), 0.005)
                    << std::endl;
      }
}
