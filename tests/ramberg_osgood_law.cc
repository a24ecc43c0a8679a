// The Ramberg-Osgood law at a point (MaterialLaw "Ramberg-Osgood"): the
// uniaxial closed form eps = sigma/E (1 + a |sigma/sigma_0|^(n-1)), the
// compliance against central differences of the strain (the Hessian of the
// same potential), its symmetry and positivity, the elastic limit a = 0,
// in plane stress and 3D; and the parameters it must refuse by name.

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/input.h>
#include <hrcontact/material/material_law.h>
#include <hrcontact/material/ramberg_osgood.h>

#include "tests.h"

using namespace dealii;
using namespace hrcontact;
using hrcontact_tests::check;

template <int dim>
std::unique_ptr<MaterialLaw<dim>>
make_law(const std::string &entries)
{
  ParameterHandler prm;
  MaterialLawFactory<dim>::declare_parameters(prm);
  prm.parse_input_from_string("subsection Material\n  set Model = "
                              "Ramberg-Osgood\n" +
                              entries + "end\n");
  return MaterialLawFactory<dim>::create(prm, Constants());
}

template <int dim>
SymmetricTensor<2, dim>
some_stress(const double scale)
{
  SymmetricTensor<2, dim> s;
  s[0][0] = 1.3 * scale;
  s[1][1] = -0.4 * scale;
  s[0][1] = 0.7 * scale;
  if (dim == 3)
    {
      s[2][2]       = 0.25 * scale;
      s[0][dim - 1] = -0.35 * scale;
      s[1][dim - 1] = 0.5 * scale;
    }
  return s;
}

template <int dim>
void
run(const std::string &plane)
{
  const std::string entries = plane + "  set Young's modulus = 200\n"
                                      "  set Poisson's ratio = 0.3\n"
                                      "  set Ramberg-Osgood coefficient = 3/7\n"
                                      "  set Ramberg-Osgood reference stress "
                                      "= 0.25\n"
                                      "  set Ramberg-Osgood exponent = 5\n";
  const auto        law     = make_law<dim>(entries);
  const Point<dim>  x;
  const double      E = 200, a = 3. / 7, s0 = 0.25, n = 5;
  std::cout << dim << "D (" << law->plane_condition_name()
            << "), linear: " << (law->is_linear() ? "yes" : "no") << '\n';

  // Uniaxial closed form.
  double worst = 0;
  for (const double sigma : {-0.6, -0.1, 0.05, 0.25, 0.8})
    {
      SymmetricTensor<2, dim> s;
      s[0][0]          = sigma;
      const double eps = law->strain(s, x)[0][0];
      const double form =
        sigma / E * (1 + a * std::pow(std::abs(sigma) / s0, n - 1));
      worst = std::max(worst, std::abs(eps - form) / std::abs(form));
    }
  std::cout << "  uniaxial eps_xx against the closed form to 1e-13: "
            << check(worst, 1e-13) << '\n';

  // The elastic law alone, a lower bound of the compliance (the power
  // term's Hessian is positive semidefinite).
  const auto elastic = make_law<dim>(plane + "  set Young's modulus = 200\n"
                                             "  set Poisson's ratio = 0.3\n");

  // The compliance is the derivative of the strain: central differences.
  double fd_error = 0, asymmetry = 0, min_energy = 1e300;
  for (const double scale : {0.02, 0.3, 1.5})
    {
      const auto sigma = some_stress<dim>(scale);
      for (unsigned int k = 0;
           k < SymmetricTensor<2, dim>::n_independent_components;
           ++k)
        {
          SymmetricTensor<2, dim> tau;
          tau[SymmetricTensor<2, dim>::unrolled_to_component_indices(k)] = 1;
          const double h  = 1e-6 * scale;
          const auto   fd = (law->strain(sigma + h * tau, x) -
                           law->strain(sigma - h * tau, x)) /
                          (2 * h);
          const auto c = law->compliance_times(sigma, tau, x);
          fd_error     = std::max(fd_error, (fd - c).norm() / c.norm());
        }
      const auto t1 = some_stress<dim>(1.),
                 t2 = some_stress<dim>(-0.3) + unit_symmetric_tensor<dim>();
      asymmetry =
        std::max(asymmetry,
                 std::abs(t1 * law->compliance_times(sigma, t2, x) -
                          t2 * law->compliance_times(sigma, t1, x)) /
                   std::abs(t1 * law->compliance_times(sigma, t2, x)));
      for (const auto &t : {t1, t2, sigma})
        {
          const double elastic_energy =
            t * elastic->compliance_times(sigma, t, x);
          min_energy =
            std::min(min_energy,
                     (t * law->compliance_times(sigma, t, x) - elastic_energy) /
                       elastic_energy);
        }
    }
  std::cout << "  compliance against central differences of the strain to "
               "1e-7: "
            << check(fd_error, 1e-7) << '\n'
            << "  compliance symmetric to 1e-13: " << check(asymmetry, 1e-13)
            << '\n'
            << "  tau : C tau at least the elastic law's (to -1e-14): "
            << (min_energy >= -1e-14 ? "yes" : "NO") << '\n';

  // a = 0 is linear elasticity.
  const auto              sigma = some_stress<dim>(0.9);
  SymmetricTensor<2, dim> linear;
  {
    ParameterHandler prm;
    MaterialLawFactory<dim>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Material\n" + plane +
                                "  set Young's modulus = 200\n"
                                "  set Poisson's ratio = 0.3\nend\n");
    linear =
      MaterialLawFactory<dim>::create(prm, Constants())->strain(sigma, x);
  }
  std::cout << "  a = 0: linear " << (elastic->is_linear() ? "yes" : "NO")
            << ", the linear law's strain to 1e-15: "
            << check((elastic->strain(sigma, x) - linear).norm() /
                       linear.norm(),
                     1e-15)
            << '\n';
}

int
main()
{
  std::cout << std::scientific << std::setprecision(6);
  run<2>("  set Plane condition = plane stress\n");
  run<3>("");

  std::cout << "Refused parameters:\n";
  for (const std::string &entries :
       {std::string("  set Plane condition = plane strain\n"),
        std::string("  set Plane condition = plane stress\n"
                    "  set Ramberg-Osgood exponent = 0.5\n"),
        std::string("  set Plane condition = plane stress\n"
                    "  set Ramberg-Osgood exponent = -2\n"),
        std::string("  set Plane condition = plane stress\n"
                    "  set Ramberg-Osgood reference stress = 0\n"),
        std::string("  set Plane condition = plane stress\n"
                    "  set Ramberg-Osgood coefficient = -1\n")})
    try
      {
        make_law<2>(entries);
        std::cout << "  NOT refused: " << entries;
      }
    catch (const InputError &e)
      {
        std::cout << "  " << e.what() << '\n';
      }
}
