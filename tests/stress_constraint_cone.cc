// The stress constraints at a point (Material/Admissible stresses): for "no
// tension" and "no compression", in 2D and 3D, the projection P onto the
// cone of multipliers (Moreau: X = P(X) + the projection onto the cone of
// admissible stresses, the two parts orthogonal, each in its cone), its
// derivative DP against central differences of P (the Hessian of the
// augmented Lagrangian term), DP symmetric and between 0 and the identity,
// linearise (one spectral decomposition) equal to the single calls,
// the violation and the factory's names.

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/input.h>
#include <hrcontact/material/stress_constraint.h>

#include "tests.h"

using namespace dealii;
using namespace hrcontact;
using hrcontact_tests::check;


template <int dim>
SymmetricTensor<2, dim>
tensor(const double a, const double b, const double c)
{
  SymmetricTensor<2, dim> s;
  s[0][0] = a;
  s[1][1] = b;
  s[0][1] = c;
  if (dim == 3)
    {
      s[2][2] = 0.5 * (a - b);
      s[0][2] = 0.3 * c;
      s[1][2] = -0.2 * a;
    }
  return s;
}

// Jacobi's iteration: the closed form of the 3D eigenvalues loses 1e-9 at
// the zero eigenvalues of a projection.
template <int dim>
double
smallest_eigenvalue(const SymmetricTensor<2, dim> &t)
{
  const auto e = eigenvectors(t, SymmetricTensorEigenvectorMethod::jacobi);
  return e[dim - 1].first;
}

template <int dim>
void
run(const std::string &name, const double sign)
{
  const auto constraint = hrcontact_tests::make_stress_constraint<dim>(name);
  std::cout << dim << "D '" << constraint->name() << "'\n";
  double moreau = 0, cones = 0, orthogonal = 0, derivative = 0, symmetric = 0,
         bounded = 0, together = 0;
  // Mixed spectra (one eigenvalue of each sign), all positive, all negative.
  for (const auto &X : {tensor<dim>(1.3, -0.4, 0.7),
                        tensor<dim>(-2.1, 0.9, -1.4),
                        tensor<dim>(2.0, 1.5, 0.2),
                        tensor<dim>(-2.0, -1.5, 0.2),
                        tensor<dim>(0.3, -0.2, 1.1)})
    {
      const SymmetricTensor<2, dim> P = constraint->project(X);
      const SymmetricTensor<2, dim> A = X - P; // the admissible part
      moreau = std::max(moreau, (P + A - X).norm() / X.norm());
      // P in the multiplier cone (sign P >= 0), A admissible (sign A <= 0).
      cones      = std::max({cones,
                             -smallest_eigenvalue<dim>(sign * P) / X.norm(),
                             -smallest_eigenvalue<dim>(-sign * A) / X.norm()});
      orthogonal = std::max(orthogonal, std::abs(P * A) / (X * X));
      // linearise (one spectrum, what the assembler calls) against the
      // single calls.
      {
        const std::vector<SymmetricTensor<2, dim>> directions = {
          tensor<dim>(1, 0, 0),
          tensor<dim>(0, 0, 1),
          tensor<dim>(0.4, -0.7, 0.3)};
        SymmetricTensor<2, dim>              P1;
        std::vector<SymmetricTensor<2, dim>> DP;
        constraint->linearise(X, directions, P1, DP);
        together = std::max(together, (P1 - P).norm() / X.norm());
        for (unsigned int k = 0; k < directions.size(); ++k)
          together = std::max(
            together,
            (DP[k] - constraint->project_derivative(X, directions[k])).norm() /
              directions[k].norm());
      }
      const double h = 1e-6;
      for (const auto &H : {tensor<dim>(1, 0, 0),
                            tensor<dim>(0, 1, 0),
                            tensor<dim>(0, 0, 1),
                            tensor<dim>(0.4, -0.7, 0.3)})
        {
          const SymmetricTensor<2, dim> fd =
            (constraint->project(X + h * H) - constraint->project(X - h * H)) /
            (2 * h);
          const SymmetricTensor<2, dim> D =
            constraint->project_derivative(X, H);
          derivative = std::max(derivative, (fd - D).norm() / H.norm());
          // 0 <= H : DP[H] <= H : H, and G : DP[H] = H : DP[G].
          bounded =
            std::max({bounded, -(H * D) / (H * H), (H * D - H * H) / (H * H)});
          const SymmetricTensor<2, dim> G = tensor<dim>(0.2, 0.9, -0.6);
          symmetric =
            std::max(symmetric,
                     std::abs(G * D -
                              H * constraint->project_derivative(X, G)));
        }
    }
  std::cout << "  X = P(X) + (X - P(X)) to 1e-14: " << check(moreau, 1e-14)
            << "\n  each part in its cone (to -1e-14): " << check(cones, 1e-14)
            << "\n  the parts orthogonal to 1e-14: " << check(orthogonal, 1e-14)
            << "\n  DP against central differences to 1e-8: "
            << check(derivative, 1e-8)
            << "\n  DP symmetric to 1e-13: " << check(symmetric, 1e-13)
            << "\n  linearise = project and project_derivative to 1e-15: "
            << check(together, 1e-15)
            << "\n  0 <= H : DP[H] <= H : H (to 1e-14): "
            << check(bounded, 1e-14) << '\n';
  // The violation: the largest principal stress of the wrong sign.
  const SymmetricTensor<2, dim> sigma = sign * tensor<dim>(2.0, -1.0, 0.);
  const auto                    e     = eigenvalues(sign * sigma);
  std::cout << "  violation = the largest wrong-sign principal stress: "
            << check(std::abs(constraint->violation(sigma) -
                              *std::max_element(e.begin(), e.end())),
                     1e-14)
            << ", admissible stresses violate nothing: "
            << check(constraint->violation(-sign * tensor<dim>(2.0, 1.0, 0.1)),
                     0.)
            << '\n';
}

int
main()
{
  std::cout << std::scientific << std::setprecision(3);
  run<2>("no tension", 1);
  run<2>("no compression", -1);
  run<3>("no tension", 1);
  run<3>("no compression", -1);
  std::cout << "'any' gives no constraint: "
            << (hrcontact_tests::make_stress_constraint<2>("any") == nullptr ?
                  "yes" :
                  "NO")
            << '\n';
  try
    {
      hrcontact_tests::make_stress_constraint<2>("no shear");
      std::cout << "unknown name NOT refused\n";
    }
  catch (const InputError &e)
    {
      std::cout << e.what() << '\n';
    }
}
