// The no-tension and no-compression patch tests with the interior point
// (issue 54), which Method = automatic, the default, takes for DGQ1 and a
// linear elastic law: the bodies of no_tension_patch_test (4^dim distorted
// cells, u = eps x on the whole boundary, E = 1000, nu = 0.3, plane stress
// in 2D) with no Method set. summary.txt must name the interior point; a
// homogeneous state must come out as the closed form's at every point to
// what the barrier's allowance (1e-6 of the largest stress) and the last
// stage's tolerance leave, 1e-5 of the largest stress or of E |eps| where
// the stress is zero (a homogeneous tension: the whole strain a fracture
// strain), in at most 12 Newton steps (8 when written); the largest
// fracture strain must be the closed form's to 1e-5 of |eps| (the errors
// were 3e-8 to 5e-6). Where the interior point does not apply,
// automatic takes the augmented Lagrangian: Pian-Sumihara stresses, a
// Ramberg-Osgood law. A traction only tension could carry is refused by
// name.

#include <hrcontact/core/input.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const double E = 1000, nu = 0.3;

  template <int dim>
  void
  report(const std::string &name,
         const std::string &constraint,
         const double       eps[3][3],
         const double       sigma[3][3],
         const double       opening)
  {
    const auto problem =
      solve_from_text<dim>(constraint_patch<dim>(constraint, eps));
    const auto &r = problem->results();
    const auto [max_err, l2_err] =
      stress_errors<dim>(r, stress_reference<dim>(sigma));
    double scale = 0, strain = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          scale  = std::max(scale, std::abs(sigma[i][j]));
          strain = std::max(strain, std::abs(eps[i][j]));
        }
    // stress_errors is relative to the closed form's norms; a zero stress
    // gives absolute errors, measured against E |eps|.
    const double absolute = (scale > 0) ? 1. : E * strain;
    std::cout << "  " << name << " ('" << constraint
              << "'): method: " << r.stress_constraint.gauss_point_method
              << ", in at most 12 Newton steps: "
              << (r.material.newton_steps <= 12 ? "yes" : "NO")
              << "\n    stresses against the closed form, max < 1e-5: "
              << check(max_err / absolute, 1e-5)
              << ", L2 < 1e-5: " << check(l2_err / absolute, 1e-5)
              << "\n    largest fracture strain against " << opening
              << " to 1e-5: "
              << check(std::abs(r.stress_constraint.largest_fracture_strain -
                                opening) /
                         strain,
                       1e-5)
              << std::endl;
  }

  /** The method automatic takes for a body with these settings. */
  std::string
  method_taken(const std::string &settings)
  {
    double eps[3][3];
    rotated(-1e-3, -2e-3, 30, eps);
    const auto problem =
      solve_from_text<2>(constraint_patch<2>("no tension", eps, settings));
    const auto &c = problem->results().stress_constraint;
    return c.residuals.empty() ? c.gauss_point_method : "augmented Lagrangian";
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6) << "2D, plane stress\n";
  for (const double degrees : {0., 30.})
    {
      const double e1 = 1e-3, e2 = -2e-3;
      double       eps[3][3], sigma[3][3];
      rotated(e1, e2, degrees, eps);
      rotated(0, E * e2, degrees, sigma);
      report<2>("crack at " + std::to_string(int(degrees)) + " degrees",
                "no tension",
                eps,
                sigma,
                e1 + nu * e2);
      double meps[3][3], msigma[3][3];
      rotated(-e1, -e2, degrees, meps);
      rotated(0, -E * e2, degrees, msigma);
      report<2>("wrinkle at " + std::to_string(int(degrees)) + " degrees",
                "no compression",
                meps,
                msigma,
                e1 + nu * e2);
    }
  {
    double eps[3][3], sigma[3][3];
    rotated(-1e-3, -2e-3, 30, eps);
    rotated(E / (1 - nu * nu) * (-1e-3 + nu * -2e-3),
            E / (1 - nu * nu) * (-2e-3 + nu * -1e-3),
            30,
            sigma);
    report<2>("compressed both ways", "no tension", eps, sigma, 0);
    double zero[3][3] = {};
    rotated(2e-3, 1e-3, 30, eps);
    report<2>("stretched both ways", "no tension", eps, zero, 2e-3);
  }
  std::cout << "3D\n";
  {
    double       eps[3][3] = {{2e-3, 0, 0}, {0, -2e-3, 0}, {0, 0, -1e-3}};
    const double s_yy      = E / (1 - nu * nu) * (eps[1][1] + nu * eps[2][2]),
                 s_zz      = E / (1 - nu * nu) * (eps[2][2] + nu * eps[1][1]);
    double sigma[3][3]     = {{0, 0, 0}, {0, s_yy, 0}, {0, 0, s_zz}};
    report<3>("crack across x",
              "no tension",
              eps,
              sigma,
              eps[0][0] + nu * (s_yy + s_zz) / E);
    double stretched[3][3] = {{2e-3, 0, 0}, {0, 1e-3, 0}, {0, 0, 3e-3}};
    double zero[3][3]      = {};
    report<3>("stretched every way", "no tension", stretched, zero, 3e-3);
  }

  std::cout << "What automatic takes:\n"
            << "  DGQ1, linear elastic: " << method_taken("") << '\n'
            << "  Pian-Sumihara, linear elastic: "
            << method_taken("subsection Finite elements\n"
                            "  set Stress element = Pian-Sumihara\nend\n")
            << '\n'
            << "  DGQ1, Ramberg-Osgood: "
            << method_taken("subsection Material\n"
                            "  set Model = Ramberg-Osgood\n"
                            "  set Ramberg-Osgood coefficient = 3/7\n"
                            "  set Ramberg-Osgood reference stress = 1\n"
                            "  set Ramberg-Osgood exponent = 5\nend\n")
            << '\n';

  std::cout << "A traction that needs tension: ";
  try
    {
      double      eps[3][3] = {};
      std::string text      = constraint_patch<2>("no tension", eps);
      text += "subsection Supports\n"
              "  set Prescribed displacements = 0 x: 0 | 2 y: 0\nend\n"
              "subsection Loads\n  set Tractions = 1: 1; 0\nend\n";
      solve_from_text<2>(text);
      std::cout << "NOT refused\n";
    }
  catch (const hrcontact::NotConvergedError &e)
    {
      const std::string what = e.what();
      std::cout << "refused, naming the cause: "
                << (what.find("no admissible stress field") !=
                        std::string::npos ?
                      "yes" :
                      "NO: " + what)
                << '\n';
    }
}
