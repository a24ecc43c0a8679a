// The cone imposed in closed form at one point (StressConstraint::
// elastic_projection, the default Method of Material/Admissible stresses):
// for "no tension" and "no compression", plane strain, plane stress and 3D,
// on strains that open no crack, one, two and (3D) three, the stress must
// meet the projection's KKT conditions, which fix it uniquely (a strictly
// convex problem): sigma in K, the fracture strain mu in the polar cone,
// mu : sigma = 0 and sigma = C (eps - mu). Its tangent must match central
// differences of sigma and be symmetric and positive semidefinite; where no
// crack opens, sigma = C eps and the tangent is C.

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/input.h>
#include <hrcontact/material/stress_constraint.h>

#include <random>

#include "tests.h"

using namespace dealii;
using namespace hrcontact;
using hrcontact_tests::check;


template <int dim>
std::array<double, dim>
spectrum(const SymmetricTensor<2, dim> &t)
{
  const auto e = eigenvectors(t, SymmetricTensorEigenvectorMethod::jacobi);
  std::array<double, dim> v;
  for (unsigned int i = 0; i < dim; ++i)
    v[i] = e[i].first;
  return v;
}

template <int dim>
void
run(const std::string &name, const double sign, const std::string &plane)
{
  const double E         = 1000;
  const auto [lambda, G] = hrcontact_tests::test_lame_constants(plane);
  const auto cone        = hrcontact_tests::make_stress_constraint<dim>(name);
  std::cout << dim << "D '" << name << "'"
            << (dim == 2 ? " (" + plane + ")" : "") << std::endl;

  std::mt19937                           gen(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  double kkt = 0, fd = 0, asym = 0, negative = 0, elastic = 0;
  // How many samples opened 0, 1, 2, 3 cracks.
  std::array<unsigned int, 4> opened{};
  for (unsigned int k = 0; k < 400; ++k)
    {
      SymmetricTensor<2, dim> eps;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          eps[i][j] = u(gen);
      // A quarter of the samples: a pure compression (no crack).
      if (k % 4 == 0)
        {
          eps = 0;
          for (unsigned int i = 0; i < dim; ++i)
            eps[i][i] = -sign * (1e-3 + std::abs(u(gen)));
          eps[0][1] = 0.1 * u(gen);
        }
      SymmetricTensor<2, dim> sigma, mu;
      SymmetricTensor<4, dim> D;
      cone->elastic_projection(eps, lambda, G, sigma, &D, &mu);
      const double scale = E * eps.norm();
      // KKT: sigma in K, mu in the polar cone, complementary, C(eps - mu).
      const auto s = spectrum<dim>(sign * sigma);
      const auto m = spectrum<dim>(sign * mu);
      const auto d = eps - mu;
      const auto C_d =
        lambda * trace(d) * unit_symmetric_tensor<dim>() + 2 * G * d;
      kkt            = std::max({kkt,
                                 std::max(s[0], 0.) / scale,
                                 std::max(-m[dim - 1], 0.) * E / scale,
                                 std::abs(sigma * mu) * E / (scale * scale),
                                 (sigma - C_d).norm() / scale});
      unsigned int n = 0;
      for (unsigned int i = 0; i < dim; ++i)
        n += (m[i] * E > 1e-9 * scale);
      ++opened[n];
      if (n == 0)
        {
          const auto C_eps =
            lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2 * G * eps;
          const SymmetricTensor<4, dim> C =
            lambda * outer_product(unit_symmetric_tensor<dim>(),
                                   unit_symmetric_tensor<dim>()) +
            2 * G * identity_tensor<dim>();
          elastic = std::max(
            {elastic, (sigma - C_eps).norm() / scale, (D - C).norm() / E});
        }
      // Central differences of sigma in each symmetric direction.
      const double h = 1e-9;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          {
            SymmetricTensor<2, dim> H;
            H[i][j] = 1;
            SymmetricTensor<2, dim> sp, sm;
            cone->elastic_projection(
              eps + h * H, lambda, G, sp, nullptr, nullptr);
            cone->elastic_projection(
              eps - h * H, lambda, G, sm, nullptr, nullptr);
            fd = std::max(fd, ((sp - sm) / (2 * h) - D * H).norm() / E);
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = a; b < dim; ++b)
                {
                  SymmetricTensor<2, dim> K;
                  K[a][b] = 1;
                  asym =
                    std::max(asym, std::abs(K * (D * H) - H * (D * K)) / E);
                }
            negative = std::min(negative, H * (D * H) / E);
          }
      // Positive semidefinite on a random direction too.
      SymmetricTensor<2, dim> H;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          H[i][j] = u(gen) * 1e3;
      negative = std::min(negative, H * (D * H) / (E * H.norm() * H.norm()));
    }
  std::cout << "  samples with 0/1/2/3 open cracks: " << opened[0] << "/"
            << opened[1] << "/" << opened[2] << "/" << opened[3] << std::endl;
  std::cout << "  KKT conditions to 1e-12: " << check(kkt, 1e-12) << std::endl;
  std::cout << "  no crack: sigma = C eps and tangent C to 1e-11: "
            << check(elastic, 1e-11) << std::endl;
  std::cout << "  tangent against central differences to 1e-5: "
            << check(fd, 1e-5) << std::endl;
  std::cout << "  tangent symmetric to 1e-13: " << check(asym, 1e-13)
            << ", positive semidefinite (to -1e-13): "
            << check(-negative, 1e-13) << std::endl;
}

int
main()
{
  for (const std::string plane : {"plane strain", "plane stress"})
    {
      run<2>("no tension", 1., plane);
      run<2>("no compression", -1., plane);
    }
  run<3>("no tension", 1., "");
  run<3>("no compression", -1., "");
  return 0;
}
