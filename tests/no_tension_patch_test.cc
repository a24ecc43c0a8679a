// Material/Admissible stresses on homogeneous states (issue 18): a body of
// distorted cells under u = eps x on its whole boundary, linear elastic
// law, E = 1000, nu = 0.3. Where eps stretches one principal direction and
// compresses the others (eps_1 + nu eps_2 > 0 in plane stress), the
// no-tension stress is uniaxial, sigma = E eps_2 n_2 n_2 (0 across the
// crack), the fracture strain mu = (eps_1 + nu eps_2) n_1 n_1: the consistent
// augmented Lagrangian (set explicitly: the default, automatic, takes the
// interior point) at the cell vertices must give it to 1e-10, whatever
// the crack's direction (0 and 30 degrees), and the mirror image under "no
// compression", and with the cone at the Gauss points. A strain that needs
// no tension gives the linear elastic
// answer to 1e-10 with nothing cracked; 3D likewise. A traction that only
// tension could carry stops with the named error.

#include <deal.II/base/point.h>

#include <hrcontact/core/input.h>
#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const double E = 1000, nu = 0.3;

  /** The body of tests.h's constraint_patch with the augmented Lagrangian
   * (the default, automatic, takes the interior point). */
  template <int dim>
  std::string
  patch(const std::string &constraint,
        const double       eps[3][3],
        const std::string &extra = "")
  {
    return constraint_patch<dim>(constraint,
                                 eps,
                                 "subsection Stress constraint iteration\n"
                                 "  set Method = augmented Lagrangian\nend\n" +
                                   extra);
  }

  /** The max and L2 errors of the run's stresses against the homogeneous
   * stress sigma (relative, stress_error). */
  template <int dim>
  std::pair<double, double>
  error_against(const hrcontact::Results<dim> &r, const double sigma[3][3])
  {
    return stress_errors<dim>(r, stress_reference<dim>(sigma));
  }

  template <int dim>
  void
  report(const std::string &name,
         const std::string &constraint,
         const double       eps[3][3],
         const double       sigma[3][3],
         const double       cracked,
         const std::string &extra = "")
  {
    const auto problem =
      solve_from_text<dim>(patch<dim>(constraint, eps, extra));
    const auto &r                = problem->results();
    const auto [max_err, l2_err] = error_against<dim>(r, sigma);
    std::cout << "  " << name << " ('" << constraint
              << "'): converged in at most 20 updates: "
              << (r.stress_constraint.residuals.size() <= 20 ? "yes" : "NO")
              << ", last residual < 1e-10: "
              << check(r.stress_constraint.residuals.back(), 1e-10)
              << "\n    stresses against the closed form, max < 1e-10: "
              << check(max_err, 1e-10)
              << ", L2 < 1e-10: " << check(l2_err, 1e-10)
              << "\n    cracked fraction "
              << r.stress_constraint.cracked_fraction << " (expected "
              << cracked << ")" << std::endl;
  }

  const std::string closed_form = "subsection Stress constraint iteration\n"
                                  "  set Method = closed-form projection\n"
                                  "end\n";

  /**
   * The same state with the cone in closed form at the Gauss points
   * (GaussPointCone): a homogeneous state takes two Newton steps (the
   * elastic one, then the projection's), and the largest fracture strain
   * must be the closed form's, `opening`; the stresses relative to the
   * closed form's largest, or to E |eps| where it is zero.
   */
  template <int dim>
  void
  report_closed_form(const ConePatchState &state)
  {
    const auto problem = solve_from_text<dim>(
      patch<dim>(state.constraint, state.eps, closed_form));
    const auto &r                 = problem->results();
    const auto [max_err, l2_err]  = error_against<dim>(r, state.sigma);
    const auto [absolute, strain] = patch_error_scales(state, E);
    std::cout << "  " << state.name << " ('" << state.constraint
              << "', closed form at the Gauss points): Newton steps "
              << r.material.newton_steps << " (at most 3: "
              << (r.material.newton_steps <= 3 ? "yes" : "NO") << ")"
              << "\n    stresses against the closed form, max < 1e-10: "
              << check(max_err / absolute, 1e-10)
              << ", L2 < 1e-10: " << check(l2_err / absolute, 1e-10)
              << "\n    cracked fraction "
              << r.stress_constraint.cracked_fraction << " (expected "
              << state.cracked << "), largest fracture strain against "
              << state.opening << " to 1e-10: "
              << check(std::abs(r.stress_constraint.largest_fracture_strain -
                                state.opening) /
                         strain,
                       1e-10)
              << std::endl;
  }

} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  std::cout << "2D, plane stress\n";
  for (const double degrees : {0., 30.})
    {
      // Stretched along n_1, compressed along n_2: eps_1 + nu eps_2 > 0.
      const double e1 = 1e-3, e2 = -2e-3;
      double       eps[3][3], sigma[3][3];
      rotated(e1, e2, degrees, eps);
      rotated(0, E * e2, degrees, sigma);
      report<2>("crack at " + std::to_string(int(degrees)) + " degrees",
                "no tension",
                eps,
                sigma,
                1);
      // The mirror image: no compression, a wrinkle along n_1.
      double meps[3][3], msigma[3][3];
      rotated(-e1, -e2, degrees, meps);
      rotated(0, -E * e2, degrees, msigma);
      report<2>("wrinkle at " + std::to_string(int(degrees)) + " degrees",
                "no compression",
                meps,
                msigma,
                1);
    }
  {
    // The cone imposed at the Gauss points instead of the vertices.
    double eps[3][3], sigma[3][3];
    rotated(1e-3, -2e-3, 30, eps);
    rotated(0, E * -2e-3, 30, sigma);
    report<2>("crack at 30 degrees, Gauss points",
              "no tension",
              eps,
              sigma,
              1,
              "subsection Stress constraint iteration\n"
              "  set Constraint points = Gauss points\nend\n");
  }
  {
    // Compressed both ways: the linear elastic (plane stress) answer.
    double eps[3][3], sigma[3][3];
    rotated(-1e-3, -2e-3, 30, eps);
    rotated(E / (1 - nu * nu) * (-1e-3 + nu * -2e-3),
            E / (1 - nu * nu) * (-2e-3 + nu * -1e-3),
            30,
            sigma);
    report<2>("compressed both ways", "no tension", eps, sigma, 0);
  }

  std::cout << "3D\n";
  {
    // Stretched along x, compressed along y and z: sigma_xx = 0 and the
    // plane-stress answer in y, z; mu_xx = eps_xx + nu (s_yy + s_zz)/E > 0.
    double       eps[3][3] = {{2e-3, 0, 0}, {0, -2e-3, 0}, {0, 0, -1e-3}};
    const double s_yy      = E / (1 - nu * nu) * (eps[1][1] + nu * eps[2][2]),
                 s_zz      = E / (1 - nu * nu) * (eps[2][2] + nu * eps[1][1]);
    double sigma[3][3]     = {{0, 0, 0}, {0, s_yy, 0}, {0, 0, s_zz}};
    report<3>("crack across x", "no tension", eps, sigma, 1);
  }

  std::cout << "The cone in closed form at the Gauss points\n";
  for (const auto &state : cone_patch_states(E, nu))
    (state.dim == 2 ? report_closed_form<2> : report_closed_form<3>)(state);

  std::cout << "A traction that needs tension:\n";
  try
    {
      double      eps[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      std::string text      = patch<2>("no tension", eps);
      text += "subsection Supports\n"
              "  set Prescribed displacements = 0 x: 0 | 2 y: 0\nend\n"
              "subsection Loads\n  set Tractions = 1: 1; 0\nend\n";
      solve_from_text<2>(text);
      std::cout << "  NOT refused\n";
    }
  catch (const hrcontact::NotConvergedError &e)
    {
      std::cout << "  " << e.what() << '\n';
    }
  std::cout << "The same, closed form:\n  "
            << tension_traction_refusal(closed_form) << '\n';
}
