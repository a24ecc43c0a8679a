// The cone's log barrier at one point (StressConstraint::barrier_projection,
// Stress constraint iteration/Method = interior point): for "no tension" and
// "no compression", plane strain, plane stress and 3D, random strains and
// three barriers tau, with and without a tension allowance delta, the
// stress must meet the barrier's optimality conditions, which fix it
// uniquely (a strictly convex problem): s sigma - delta I negative definite,
// sigma = C (eps - mu) and (s sigma - delta I) (s mu) = -tau I. Its tangent
// must match central differences and be symmetric positive definite, and
// as tau -> 0 the stress must approach the closed-form projection within
// the barrier's reach sqrt(tau E).

#include <hrcontact/material/stress_constraint.h>

#include <random>

#include "tests.h"

using namespace dealii;
using namespace hrcontact;
using hrcontact_tests::check;

template <int dim>
void
run(const std::string &name, const double sign, const std::string &plane)
{
  const double E         = 1000;
  const auto [lambda, G] = hrcontact_tests::test_lame_constants(plane);
  const auto cone        = hrcontact_tests::make_stress_constraint<dim>(name);
  std::cout << dim << "D '" << name << "'"
            << (dim == 2 ? " (" + plane + ")" : "") << std::endl;
  const auto I = unit_symmetric_tensor<dim>();

  std::mt19937                           gen(11);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  double inside = -1, law = 0, central = 0, fd = 0, asym = 0, definite = 1,
         reach = 0;
  for (const double t : {1e-2, 1e-5, 1e-8})
    for (const double allowance : {0., 1e-3})
      for (unsigned int k = 0; k < 100; ++k)
        {
          SymmetricTensor<2, dim> eps;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              eps[i][j] = u(gen);
          // tau in units of s^2 / E, s = E 1e-3 the stress scale.
          const double tau = t * E * 1e-6, delta = allowance * E * 1e-3;
          SymmetricTensor<2, dim> sigma, mu;
          SymmetricTensor<4, dim> D;
          cone->barrier_projection(eps, lambda, G, tau, delta, sigma, &D, &mu);
          const double scale = E * 1e-3;
          // Strictly inside the shifted cone.
          const auto shifted = sign * sigma - delta * I;
          const auto ev =
            eigenvectors(shifted, SymmetricTensorEigenvectorMethod::jacobi);
          inside = std::max(inside, ev[0].first / scale);
          // The law and the central path.
          const auto d   = eps - mu;
          const auto C_d = lambda * trace(d) * I + 2 * G * d;
          law            = std::max(law, (sigma - C_d).norm() / scale);
          Tensor<2, dim> product =
            Tensor<2, dim>(shifted) * Tensor<2, dim>(sign * mu);
          for (unsigned int i = 0; i < dim; ++i)
            product[i][i] += tau;
          central = std::max(central, product.norm() / tau);
          // Central differences, the step within the barrier's reach.
          const double h = 1e-3 * std::sqrt(tau / E);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              {
                SymmetricTensor<2, dim> H;
                H[i][j] = 1;
                SymmetricTensor<2, dim> sp, sm;
                cone->barrier_projection(
                  eps + h * H, lambda, G, tau, delta, sp, nullptr, nullptr);
                cone->barrier_projection(
                  eps - h * H, lambda, G, tau, delta, sm, nullptr, nullptr);
                fd = std::max(fd, ((sp - sm) / (2 * h) - D * H).norm() / E);
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = a; b < dim; ++b)
                    {
                      SymmetricTensor<2, dim> K;
                      K[a][b] = 1;
                      asym =
                        std::max(asym, std::abs(K * (D * H) - H * (D * K)) / E);
                    }
              }
          SymmetricTensor<2, dim> H;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              H[i][j] = u(gen) * 1e3;
          definite =
            std::min(definite, H * (D * H) / (E * H.norm() * H.norm()));
          // Against the closed form (no allowance): within sqrt(tau E).
          if (allowance == 0)
            {
              SymmetricTensor<2, dim> closed;
              cone->elastic_projection(
                eps, lambda, G, closed, nullptr, nullptr);
              reach =
                std::max(reach, (sigma - closed).norm() / std::sqrt(tau * E));
            }
        }
  std::cout << "  strictly inside the (shifted) cone: " << check(inside, -1e-30)
            << std::endl;
  std::cout << "  sigma = C (eps - mu) to 1e-12: " << check(law, 1e-12)
            << std::endl;
  // Products of s and fracture strains near 1e-3 keep fewer digits at the
  // smallest tau.
  std::cout << "  (s sigma - delta) (s mu) = -tau I to 1e-6 of tau: "
            << check(central, 1e-6) << std::endl;
  std::cout << "  tangent against central differences to 1e-5: "
            << check(fd, 1e-5) << std::endl;
  std::cout << "  tangent symmetric to 1e-12: " << check(asym, 1e-12)
            << ", positive definite on random directions: "
            << check(-definite, -1e-300) << std::endl;
  std::cout << "  closed form within 3 sqrt(tau E): " << check(reach, 3.)
            << std::endl;
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
