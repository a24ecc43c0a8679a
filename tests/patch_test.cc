// Patch tests on distorted meshes, 2D (plane strain) and 3D: a uniform stress
// state must be reproduced to round-off by the HR discretisation with DGQ1
// stresses and with the Pian-Sumihara (3D: Pian-Tong) assumed-stress field, (a)
// driven by the linear displacement field of that state prescribed on the whole
// boundary, (b) driven by tractions on a body held by rollers. The strain of
// the state is computed here independently of the library's compliance.

#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

using namespace hrcontact_tests;

template <int dim>
std::string
patch_text(const std::string &element,
           const std::string &supports_and_loads,
           const std::string &reference)
{
  return "set Dimension = " + std::to_string(dim) +
         "\n"
         "subsection Geometry\n"
         "  set Grid generator = subdivided_hyper_cube\n"
         "  set Grid arguments = 4 : 0 : 1 : true\n"
         "  set Distortion = 0.3\n"
         "end\n"
         "subsection Material\n"
         "  set Young's modulus = 1000\n"
         "  set Poisson's ratio = 0.3\n"
         "  set Plane condition = plane strain\n"
         "end\n"
         "subsection Finite elements\n"
         "  set Stress element = " +
         element + "\nend\n" + supports_and_loads +
         "subsection Postprocess\n"
         "  set Reference stress = " +
         reference + "\nend\n";
}

template <int dim>
void
report(const std::string               &name,
       const hrcontact::HRProblem<dim> &problem,
       const std::string               &reference)
{
  const auto exact = hrcontact::make_function<dim>(
    reference,
    hrcontact::MixedSpaces<dim>::n_stress_components,
    {},
    "reference");
  const auto [max_err, l2_err] =
    hrcontact::stress_error(problem.results().spaces,
                            problem.results().stress,
                            *exact);
  std::cout << "  " << name << ": "
            << problem.results().triangulation().n_active_cells()
            << " distorted cells, max relative stress error < 1e-10: "
            << check(max_err, 1e-10)
            << ", L2 relative error < 1e-10: " << check(l2_err, 1e-10)
            << std::endl;
}

template <int dim>
void
run(const std::string &element)
{
  std::cout << "dim = " << dim << ", stress element " << element << std::endl;
  const double E = 1000, nu = 0.3;
  double       s[3][3] = {{3., 1.5, -0.7}, {1.5, -2., 0.4}, {-0.7, 0.4, 0.5}};
  if (dim == 2)
    s[2][2] = nu * (s[0][0] + s[1][1]); // plane strain: eps_zz = 0
  const double trace = s[0][0] + s[1][1] + s[2][2];
  double       eps[3][3];
  for (unsigned int a = 0; a < 3; ++a)
    for (unsigned int b = 0; b < 3; ++b)
      eps[a][b] = ((1 + nu) * s[a][b] - (a == b ? nu * trace : 0.)) / E;

  std::ostringstream reference;
  reference << std::setprecision(17);
  for (unsigned int c = 0; c < hrcontact::MixedSpaces<dim>::n_stress_components;
       ++c)
    {
      const auto ab = hrcontact::MixedSpaces<dim>::stress_component_indices(c);
      reference << (c ? "; " : "") << s[ab.first][ab.second];
    }

  // (a) u = eps x on every boundary.
  {
    std::ostringstream t;
    t << linear_displacement_supports<dim>(eps);
    report<dim>("displacement patch",
                *solve_from_text<dim>(
                  patch_text<dim>(element, t.str(), reference.str())),
                reference.str());
  }

  // (b) normal stresses only, by tractions on the faces x = 1, y = 1 (z = 1)
  // and rollers on x = 0, y = 0 (z = 0).
  {
    std::ostringstream ref, t;
    ref << std::setprecision(17);
    for (unsigned int c = 0;
         c < hrcontact::MixedSpaces<dim>::n_stress_components;
         ++c)
      ref << (c ? "; " : "") << (c < dim ? s[c][c] : 0.);
    t << std::setprecision(17) << "subsection Supports\n"
      << "  set Prescribed displacements = 0 x: 0 | 2 y: 0"
      << (dim == 3 ? " | 4 z: 0" : "") << "\nend\n"
      << "subsection Loads\n  set Tractions = ";
    for (unsigned int d = 0; d < dim; ++d)
      {
        t << (d ? " | " : "") << 2 * d + 1 << ": ";
        for (unsigned int a = 0; a < dim; ++a)
          t << (a ? "; " : "") << (a == d ? s[d][d] : 0.);
      }
    t << "\nend\n";
    auto problem =
      solve_from_text<dim>(patch_text<dim>(element, t.str(), ref.str()));
    report<dim>("traction patch", *problem, ref.str());
    // The rollers carry the load: reaction on x = 0 balances s_xx * area.
    double rx = 0;
    for (unsigned int k = 0;
         k < problem->results().system.prescribed_rows.size();
         ++k)
      rx += problem->results().reactions.support[k] *
            problem->results()
              .system.rows[problem->results().system.prescribed_rows[k]]
              .combination[0]
              .second;
    std::cout << "  traction patch: roller reaction in x = " << rx
              << " (expected " << -s[0][0] << ")" << std::endl;
  }
}

int
main()
{
  std::cout << std::setprecision(6);
  for (const std::string element : {"DGQ1", "Pian-Sumihara"})
    {
      run<2>(element);
      run<3>(element);
    }
}
