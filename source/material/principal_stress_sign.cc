#include <deal.II/base/symmetric_tensor.h>

#include <hrcontact/material/principal_stress_sign.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    std::array<std::pair<double, Tensor<1, dim>>, dim>
    spectrum(const SymmetricTensor<2, dim> &X)
    {
      return eigenvectors(X, SymmetricTensorEigenvectorMethod::jacobi);
    }
  } // namespace

  template <int dim>
  PrincipalStressSign<dim>::PrincipalStressSign(const double sign)
    : sign(sign)
  {}

  template <int dim>
  std::string
  PrincipalStressSign<dim>::name() const
  {
    return sign > 0 ? "no tension" : "no compression";
  }

  namespace
  {
    /** P_+ of the spectrum e (of s X), times s. */
    template <int dim>
    SymmetricTensor<2, dim>
    positive_part(const std::array<std::pair<double, Tensor<1, dim>>, dim> &e,
                  const double sign)
    {
      SymmetricTensor<2, dim> P;
      for (unsigned int i = 0; i < dim; ++i)
        if (e[i].first > 0)
          P += e[i].first * symmetrize(outer_product(e[i].second, e[i].second));
      return sign * P;
    }

    /** DP_+[H] at the spectrum e (Loewner's divided differences). */
    template <int dim>
    SymmetricTensor<2, dim>
    derivative(const std::array<std::pair<double, Tensor<1, dim>>, dim> &e,
               const SymmetricTensor<2, dim>                            &H)
    {
      SymmetricTensor<2, dim> D;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            const double li = e[i].first, lj = e[j].first;
            double       theta;
            if (li > 0 && lj > 0)
              theta = 1;
            else if (li <= 0 && lj <= 0)
              theta = 0;
            else // one positive, one not: li != lj
              theta = (std::max(li, 0.) - std::max(lj, 0.)) / (li - lj);
            if (theta == 0)
              continue;
            const double h = e[i].second * (H * e[j].second);
            D +=
              theta * h * symmetrize(outer_product(e[i].second, e[j].second));
          }
      return D;
    }
  } // namespace

  template <int dim>
  SymmetricTensor<2, dim>
  PrincipalStressSign<dim>::project(const SymmetricTensor<2, dim> &X) const
  {
    return positive_part<dim>(spectrum<dim>(sign * X), sign);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  PrincipalStressSign<dim>::project_derivative(
    const SymmetricTensor<2, dim> &X,
    const SymmetricTensor<2, dim> &H) const
  {
    return derivative<dim>(spectrum<dim>(sign * X), H);
  }

  template <int dim>
  void
  PrincipalStressSign<dim>::linearise(
    const SymmetricTensor<2, dim>              &X,
    const std::vector<SymmetricTensor<2, dim>> &H,
    SymmetricTensor<2, dim>                    &P,
    std::vector<SymmetricTensor<2, dim>>       &DP) const
  {
    const auto e = spectrum<dim>(sign * X);
    P            = positive_part<dim>(e, sign);
    DP.resize(H.size());
    for (unsigned int k = 0; k < H.size(); ++k)
      DP[k] = derivative<dim>(e, H[k]);
  }

  template <int dim>
  double
  PrincipalStressSign<dim>::violation(
    const SymmetricTensor<2, dim> &sigma) const
  {
    const auto e = eigenvalues(sign * sigma);
    return std::max(*std::max_element(e.begin(), e.end()), 0.);
  }

  template <int dim>
  double
  PrincipalStressSign<dim>::opening(const SymmetricTensor<2, dim> &mu) const
  {
    const auto e = eigenvalues(mu);
    double     m = 0;
    for (const double v : e)
      m = std::max(m, std::abs(v));
    return m;
  }

  template <int dim>
  void
  PrincipalStressSign<dim>::elastic_projection(
    const SymmetricTensor<2, dim> &eps,
    const double                   lambda,
    const double                   shear,
    SymmetricTensor<2, dim>       &sigma,
    SymmetricTensor<4, dim>       *tangent,
    SymmetricTensor<2, dim>       *fracture) const
  {
    // No tension on s eps; sorted e_1 >= e_2 (>= e_3).
    const auto   e     = spectrum<dim>(sign * eps);
    const double G2    = 2 * shear;
    double       scale = 0;
    for (unsigned int i = 0; i < dim; ++i)
      scale = std::max(scale, std::abs(e[i].first));
    const double            tol = 1e-13 * scale * (lambda + G2);
    std::array<double, dim> s{}, m{};
    unsigned int            cracked = dim;
    double                  tr      = 0;
    for (unsigned int n = 0; n <= dim; ++n)
      {
        double sum = 0;
        for (unsigned int j = n; j < dim; ++j)
          sum += e[j].first;
        tr        = sum * G2 / (G2 + n * lambda);
        bool fits = true;
        for (unsigned int j = 0; j < dim; ++j)
          {
            s[j] = (j < n) ? 0. : lambda * tr + G2 * e[j].first;
            m[j] = (j < n) ? e[j].first + lambda * tr / G2 : 0.;
            if (s[j] > tol || m[j] * (lambda + G2) < -tol)
              fits = false;
          }
        if (fits)
          {
            cracked = n;
            break;
          }
      }
    // The last candidate (every direction open) fits up to round-off when
    // no earlier one did: keep it.
    std::array<SymmetricTensor<2, dim>, dim> N;
    for (unsigned int i = 0; i < dim; ++i)
      N[i] = symmetrize(outer_product(e[i].second, e[i].second));
    sigma = 0;
    for (unsigned int j = cracked; j < dim; ++j)
      sigma += s[j] * N[j];
    sigma *= sign;
    if (fracture)
      {
        *fracture = 0;
        for (unsigned int i = 0; i < cracked; ++i)
          *fracture += m[i] * N[i];
        *fracture *= sign;
      }
    if (!tangent)
      return;
    // d sigma_j / d e_k on the uncracked directions, then the spins.
    *tangent                 = 0;
    const double lambda_open = lambda * G2 / (G2 + cracked * lambda);
    for (unsigned int j = cracked; j < dim; ++j)
      for (unsigned int k = cracked; k < dim; ++k)
        *tangent +=
          (lambda_open + (j == k ? G2 : 0.)) * outer_product(N[j], N[k]);
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i + 1; j < dim; ++j)
        {
          const double gap = e[i].first - e[j].first;
          double       spin;
          if (gap > 1e-12 * scale)
            spin = (s[i] - s[j]) / gap;
          else
            spin = (i >= cracked) ? G2 : 0.; // both closed: elastic
          const SymmetricTensor<2, dim> M =
            symmetrize(outer_product(e[i].second, e[j].second)) * std::sqrt(2.);
          *tangent += spin * outer_product(M, M);
        }
  }

  template class PrincipalStressSign<2>;
  template class PrincipalStressSign<3>;

  namespace
  {
    template <int dim>
    bool
    register_both()
    {
      StressConstraintFactory<dim>::register_constraint("no tension", [] {
        return std::make_unique<PrincipalStressSign<dim>>(1.);
      });
      StressConstraintFactory<dim>::register_constraint("no compression", [] {
        return std::make_unique<PrincipalStressSign<dim>>(-1.);
      });
      return true;
    }
    const bool registered_2d = register_both<2>();
    const bool registered_3d = register_both<3>();
  } // namespace
} // namespace hrcontact
