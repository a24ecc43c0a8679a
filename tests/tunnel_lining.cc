// The tunnel lining scene (parameters/tunnel.prm) at 3 and 4 refinements:
// - the applied loads against closed-form integrals of Terzaghi's pressures
//   and the self weight (lateral load exact: n_x ds = dy on every chord and
//   the pressure is linear in y: to 1e-9, summary.txt keeps 10 digits; vertical
//   within 1 %, the face that crosses the springline is split by its Gauss
//   points);
// - global equilibrium: support and contact reactions balance the applied
//   load to 1e-8 relative;
// - Signorini sign conditions on every extrados node;
// - the pressed zones along the extrados: same number at both meshes, each
//   end within 1.5 coarse node spacings.

#include <hrcontact/geometry/tunnel_lining.h>

#include "tests.h"

struct Zones
{
  std::vector<std::pair<double, double>> zones;
  double                                 spacing;
};

Zones
run(const unsigned int refinements)
{
  auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/tunnel.prm") +
    "subsection Geometry\n  set Global refinements = " +
    std::to_string(refinements) +
    "\nend\nsubsection Output\n  set Write solution = false\n  set Print "
    "timing = false\n  set Output directory = results\nend\n");
  std::ostringstream quiet;
  problem->output_results(quiet);
  const auto  &summary = problem->results().summary;
  const auto  &c       = problem->results().scene.constants;
  const auto  &lining  = *problem->results().scene.lining;
  const double pi      = dealii::numbers::PI;
  std::cout << "tunnel lining, " << refinements
            << " refinements: " << summary.get("cells")
            << " cells, converged = " << summary.get("converged") << ", path "
            << summary.get("solution_path") << std::endl;

  // Closed-form loads on the half lining.
  const double sv = c.at("sv"), Ka = c.at("Ka"), gs = c.at("gs"),
               coh = c.at("c"), gc = c.at("gc");
  const double y_top = lining.R_c + lining.t_c;
  const double y_bot = lining.R_c - lining.H - lining.t_i;
  const double m     = y_top - y_bot;
  const double Fx =
    -((Ka * sv - 2 * coh * std::sqrt(Ka)) * m + Ka * gs * m * m / 2);
  // Area by Green's theorem over the two arcs of each boundary.
  auto arc =
    [](const double cx, const double cy, const double R, double a, double b) {
      return 0.5 * (R * R * (b - a) + R * (cx * (std::sin(b) - std::sin(a)) -
                                           cy * (std::cos(b) - std::cos(a))));
    };
  const double A_out =
    arc(0, lining.y_invert, lining.R_i + lining.t_i, -pi / 2, lining.phi_out) +
    arc(0, 0, lining.R_c + lining.t_c, lining.theta_out, pi / 2);
  const double A_in =
    arc(0, lining.y_invert, lining.R_i, -pi / 2, lining.phi_in) +
    arc(0, 0, lining.R_c, lining.theta_in, pi / 2);
  const double Fy     = -sv * (lining.R_c + lining.t_c) - gc * (A_out - A_in);
  const double load_x = summary.get_double("total_load_x");
  const double load_y = summary.get_double("total_load_y");
  // summary.txt keeps 10 significant digits.
  std::cout << "  lateral load vs -int sh dy to 1e-9:       "
            << hrcontact_tests::check(std::abs(load_x / Fx - 1), 1e-9)
            << "\n  vertical load vs sv b + self weight to 1e-2: "
            << hrcontact_tests::check(std::abs(load_y / Fy - 1), 1e-2) << "\n";

  // Global equilibrium relative to the applied load.
  const double imbalance =
    std::hypot(load_x + summary.get_double("total_reaction_x"),
               load_y + summary.get_double("total_reaction_y")) /
    std::hypot(load_x, load_y);
  std::cout << "  reactions balance the load to 1e-8:       "
            << hrcontact_tests::check(imbalance, 1e-8) << std::endl;
  hrcontact_tests::print_kkt(*problem);

  // Pressed zones "a - b; c - d" from summary.txt.
  Zones result;
  result.spacing = lining.extrados_length() /
                   (problem->results().system.contact_rows.size() - 1);
  std::cout << "  pressed zones along the extrados:";
  for (const std::string &z :
       hrcontact::split_and_trim(summary.get("lining_pressed_zones"), ';'))
    {
      const auto ends = hrcontact::split_and_trim(z, '-');
      result.zones.emplace_back(std::stod(ends.at(0)), std::stod(ends.at(1)));
      std::cout << " [" << std::fixed << std::setprecision(2)
                << result.zones.back().first << ", "
                << result.zones.back().second << "]" << std::defaultfloat;
    }
  std::cout << std::endl;
  return result;
}

int
main()
{
  const Zones coarse = run(3), fine = run(4);
  bool        same  = coarse.zones.size() == fine.zones.size();
  double      worst = 0;
  for (unsigned int k = 0; same && k < coarse.zones.size(); ++k)
    worst = std::max({worst,
                      std::abs(coarse.zones[k].first - fine.zones[k].first),
                      std::abs(coarse.zones[k].second - fine.zones[k].second)});
  std::cout << "same number of pressed zones: " << (same ? "yes" : "NO")
            << "\nzone ends move by less than 1.5 coarse spacings: "
            << hrcontact_tests::check(worst / coarse.spacing, 1.5) << std::endl;
}
