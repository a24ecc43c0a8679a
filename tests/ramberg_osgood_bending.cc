// Pure bending of a Ramberg-Osgood beam in plane stress (issue 18,
// parameters/ramberg-osgood-beam.prm): the bending moment the ends' supports
// carry must converge under refinement to the beam-theory moment
// M = int sigma(kappa y) y dy, with sigma(eps) the uniaxial law inverted
// (Newton here, Gauss-Legendre over the section: independent of the
// library). The moment is summed from the support reactions at x = L times
// their lever arms; their resultant must vanish (no axial force). The
// scene's exact mid-span deflection is checked too.

#include <deal.II/base/quadrature_lib.h>

#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const double E = 70e9, a = 3. / 7., s_0 = 200e6, n = 5., D = 0.1, kappa = 0.1,
               L = 1;

  /** sigma with sigma/E (1 + a |sigma/s_0|^(n-1)) = eps (monotone). */
  double
  uniaxial_stress(const double eps)
  {
    double sigma = E * eps;
    for (unsigned int k = 0; k < 100; ++k)
      {
        const double r    = std::pow(std::abs(sigma) / s_0, n - 1);
        const double f    = sigma / E * (1 + a * r) - eps;
        const double df   = (1 + a * n * r) / E;
        const double step = f / df;
        sigma -= step;
        if (std::abs(step) <= 1e-15 * std::abs(sigma))
          break;
      }
    return sigma;
  }

  double
  beam_theory_moment()
  {
    const dealii::QGauss<1> gauss(30);
    double                  m = 0;
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double y = gauss.point(q)[0] * D / 2;
        m += 2 * uniaxial_stress(kappa * y) * y * gauss.weight(q) * D / 2;
      }
    return m;
  }
} // namespace

/** The moment and |resultant| / sum |r_x| of the reactions at x = L. */
std::pair<double, double>
end_moment(const hrcontact::Results<2> &res)
{
  double moment = 0, resultant = 0, total = 0;
  for (unsigned int k = 0; k < res.system.prescribed_rows.size(); ++k)
    {
      const auto &row = res.system.rows[res.system.prescribed_rows[k]];
      const auto &x   = res.system.node_coordinates[row.node];
      // The x rows of the end x = L: c = (1, 0).
      if (std::abs(x[0] - L) < 1e-12 && row.combination[0].second == 1)
        {
          const double rx = res.reactions.support[k];
          moment += rx * x[1];
          resultant += rx;
          total += std::abs(rx);
        }
    }
  return {std::abs(moment), std::abs(resultant) / total};
}

int
main()
{
  const std::string scene = read_file(std::string(SOURCE_DIR) +
                                      "/../parameters/ramberg-osgood-beam.prm");
  const double      M     = beam_theory_moment();
  std::cout << std::setprecision(6) << "beam theory: M = " << M
            << " N m/m (elastic " << E * kappa * D * D * D / 12
            << "), outer fibre " << uniaxial_stress(kappa * D / 2) / 1e6
            << " MPa\n";
  // The same mesh with the linear law (a = 0): the elastic moment E I kappa
  // is overestimated as much, the parasitic shear of bilinear elements in
  // bending (HR with DGQ1 stresses on rectangles is the Q1 displacement
  // method, tests/hr_equals_q1), which falls as h^2.
  for (unsigned int r = 0; r <= 1; ++r)
    {
      const auto problem = solve_from_text<2>(
        scene +
        "subsection Geometry\n  set Global refinements = " + std::to_string(r) +
        "\nend\nsubsection Material\n  set Ramberg-Osgood coefficient = "
        "0\nend\n");
      std::cout << "linear law, " << (1u << r)
                << " cell(s) across: M_h / (E I kappa) - 1 = "
                << end_moment(problem->results()).first /
                       (E * kappa * D * D * D / 12) -
                     1
                << '\n';
    }
  std::cout << "Ramberg-Osgood:\n"
            << "cells across | Newton steps | M_h / M - 1 | rate | "
               "|resultant| / sum |r_x| < 1e-10 | deflection error\n";
  double previous = 0, rate = 0;
  for (unsigned int r = 0; r <= 4; ++r)
    {
      const auto problem = solve_from_text<2>(
        scene + "subsection Geometry\n  set Global refinements = " +
        std::to_string(r) + "\nend\n");
      const auto &res                = problem->results();
      const auto [moment, resultant] = end_moment(res);
      const double error             = moment / M - 1;
      const double deflection =
        hrcontact::point_value(res, dealii::Point<2>(L / 2, 0), "uy");
      std::cout << std::setw(12) << (1u << r) << " | " << std::setw(12)
                << res.material.newton_steps << " | " << std::scientific
                << std::setprecision(3) << std::setw(10) << error << " | "
                << std::fixed << std::setprecision(2)
                << (previous != 0 ? std::log2(std::abs(previous / error)) : 0.)
                << " | " << check(resultant, 1e-10) << " | " << std::scientific
                << std::setprecision(2) << deflection / (-kappa * L * L / 8) - 1
                << std::endl
                << std::setprecision(6) << std::defaultfloat;
      if (previous != 0)
        rate = std::log2(std::abs(previous / error));
      previous = error;
    }
  std::cout << "second order (last rate >= 1.9): " << check(-rate, -1.9)
            << ", M_h within 0.3 % at 16 cells across: "
            << check(std::abs(previous), 3e-3) << std::endl;
}
