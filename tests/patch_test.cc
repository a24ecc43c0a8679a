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
  const auto [max_err, l2_err] =
    stress_errors<dim>(problem.results(), reference);
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
  double s[3][3], eps[3][3];
  patch_state<dim>(1000, 0.3, s, eps);
  const std::string reference = stress_reference<dim>(s);

  // (a) u = eps x on every boundary.
  report<dim>("displacement patch",
              *solve_from_text<dim>(patch_text<dim>(
                element, linear_displacement_supports<dim>(eps), reference)),
              reference);

  // (b) normal stresses only, by tractions on the faces x = 1, y = 1 (z = 1)
  // and rollers on x = 0, y = 0 (z = 0).
  {
    const std::string ref     = stress_reference<dim>(s, true);
    auto              problem = solve_from_text<dim>(
      patch_text<dim>(element, normal_traction_supports<dim>(s), ref));
    report<dim>("traction patch", *problem, ref);
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
