// Patch tests of a nonlinear law (Ramberg-Osgood, Hencky deformation theory)
// on distorted meshes, 2D (plane stress) and 3D: the material Newton
// iteration (MaterialIteration) must reproduce a uniform stress state well
// into the power-law range, (a) driven by the displacement field u = eps x
// of the law's strain prescribed on the whole boundary: the stresses to
// 1e-10; (b) driven by tractions on a body held by rollers: the stresses
// to 1e-10 and the displacement of the far corner, eps x, to 1e-10. The
// strain of the state is computed here from the law's closed form,
// independently of the library. The Newton steps converge quadratically:
// the number taken is printed, and the last stress change must be below
// the tolerance.

#include <deal.II/base/point.h>

#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  // E, nu and the law: eps = ((1+nu) s - nu tr(s) I)/E
  //                        + 3/2 a/E (s_eq/s_0)^(n-1) dev(s).
  const double E = 1000, nu = 0.3, a = 3. / 7., s_0 = 2., n = 5.;

  template <int dim>
  std::string
  material_text()
  {
    return std::string("subsection Material\n"
                       "  set Model = Ramberg-Osgood\n"
                       "  set Young's modulus = 1000\n"
                       "  set Poisson's ratio = 0.3\n") +
           (dim == 2 ? "  set Plane condition = plane stress\n" : "") +
           "  set Ramberg-Osgood coefficient = 3/7\n"
           "  set Ramberg-Osgood reference stress = 2\n"
           "  set Ramberg-Osgood exponent = 5\n"
           "end\n";
  }

  template <int dim>
  std::string
  patch_text(const std::string &supports_and_loads,
             const std::string &reference)
  {
    return "set Dimension = " + std::to_string(dim) +
           "\n"
           "subsection Geometry\n"
           "  set Grid generator = subdivided_hyper_cube\n"
           "  set Grid arguments = 4 : 0 : 1 : true\n"
           "  set Distortion = 0.3\n"
           "end\n" +
           material_text<dim>() + supports_and_loads +
           "subsection Postprocess\n"
           "  set Reference stress = " +
           reference + "\nend\n";
  }

  /** The law's strain of the 3D stress s (plane stress: s_zz = 0). */
  void
  law_strain(const double s[3][3], double eps[3][3])
  {
    const double trace = s[0][0] + s[1][1] + s[2][2];
    double       dev[3][3], j2 = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        {
          dev[i][j] = s[i][j] - (i == j ? trace / 3 : 0.);
          j2 += 0.5 * dev[i][j] * dev[i][j];
        }
    const double s_eq = std::sqrt(3 * j2);
    const double g    = 1.5 * a / E * std::pow(s_eq / s_0, n - 1);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        eps[i][j] =
          ((1 + nu) * s[i][j] - (i == j ? nu * trace : 0.)) / E + g * dev[i][j];
  }

  template <int dim>
  void
  report(const std::string               &name,
         const hrcontact::HRProblem<dim> &problem,
         const std::string               &reference)
  {
    const auto &r                = problem.results();
    const auto [max_err, l2_err] = stress_errors<dim>(r, reference);
    std::cout << "  " << name << ": " << r.triangulation().n_active_cells()
              << " distorted cells, " << r.material.newton_steps
              << " Newton steps, last stress change < 1e-10: "
              << check(r.material.changes.empty() ? 1. :
                                                    r.material.changes.back(),
                       1e-10)
              << "\n    max relative stress error < 1e-10: "
              << check(max_err, 1e-10)
              << ", L2 relative error < 1e-10: " << check(l2_err, 1e-10)
              << std::endl;
  }

  template <int dim>
  void
  run()
  {
    std::cout << "dim = " << dim << (dim == 2 ? " (plane stress)" : "")
              << std::endl;
    double s[3][3] = {{3., 1.5, -0.7}, {1.5, -2., 0.4}, {-0.7, 0.4, 0.5}};
    if (dim == 2)
      s[0][2] = s[2][0] = s[1][2] = s[2][1] = s[2][2] = 0;
    double eps[3][3];
    law_strain(s, eps);
    {
      double trace = s[0][0] + s[1][1] + s[2][2], j2 = 0;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            const double d = s[i][j] - (i == j ? trace / 3 : 0.);
            j2 += 0.5 * d * d;
          }
      std::cout << "  s_eq / s_0 = " << std::sqrt(3 * j2) / s_0 << std::endl;
    }

    const std::string reference = stress_reference<dim>(s);

    // (a) u = eps x on every boundary.
    {
      std::ostringstream t;
      t << linear_displacement_supports<dim>(eps);
      report<dim>("displacement patch",
                  *solve_from_text<dim>(patch_text<dim>(t.str(), reference)),
                  reference);
    }

    // (b) normal stresses only, by tractions on the faces x = 1, y = 1
    // (z = 1) and rollers on x = 0, y = 0 (z = 0).
    {
      double sn[3][3] = {{s[0][0], 0, 0}, {0, s[1][1], 0}, {0, 0, s[2][2]}};
      double en[3][3];
      law_strain(sn, en);
      const std::string ref     = stress_reference<dim>(sn, true);
      auto              problem = solve_from_text<dim>(
        patch_text<dim>(normal_traction_supports<dim>(sn), ref));
      report<dim>("traction patch", *problem, ref);
      // The far corner moves by eps x: the law's normal strains.
      dealii::Point<dim> corner;
      for (unsigned int d = 0; d < dim; ++d)
        corner[d] = 1;
      double error = 0;
      for (unsigned int d = 0; d < dim; ++d)
        error = std::max(error,
                         std::abs(
                           hrcontact::point_value(problem->results(),
                                                  corner,
                                                  std::string("u") + "xyz"[d]) -
                           en[d][d]) /
                           std::abs(en[d][d]));
      std::cout << "    corner displacement against the law's strains "
                << "< 1e-10 (relative): " << check(error, 1e-10)
                << "\n    (e_xx = " << en[0][0] << ", of which elastic "
                << (sn[0][0] - nu * (sn[1][1] + sn[2][2])) / E << ")"
                << std::endl;
    }
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  run<2>();
  run<3>();
}
