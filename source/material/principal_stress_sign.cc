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

  namespace
  {
    /**
     * The spins of an isotropic function of a symmetric tensor: (s_i -
     * s_j) / (e_i - e_j) on each pair of principal directions, @p coincide
     * (i, j) where the gap is below @p small.
     */
    template <int dim, typename Limit>
    void
    add_spins(const std::array<std::pair<double, Tensor<1, dim>>, dim> &e,
              const std::array<double, dim>                            &s,
              const double                                              small,
              SymmetricTensor<4, dim>                                  &tangent,
              const Limit &coincide)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i + 1; j < dim; ++j)
          {
            const double gap = e[i].first - e[j].first;
            const double spin =
              (gap > small) ? (s[i] - s[j]) / gap : coincide(i, j);
            const SymmetricTensor<2, dim> M =
              symmetrize(outer_product(e[i].second, e[j].second)) *
              std::sqrt(2.);
            tangent += spin * outer_product(M, M);
          }
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
    // Where two strains coincide: both closed is elastic, else no stiffness.
    add_spins<dim>(e,
                   s,
                   1e-12 * scale,
                   *tangent,
                   [&](const unsigned int i, const unsigned int) {
                     return (i >= cracked) ? G2 : 0.;
                   });
  }

  template <int dim>
  void
  PrincipalStressSign<dim>::barrier_projection(
    const SymmetricTensor<2, dim> &eps,
    const double                   lambda,
    const double                   shear,
    const double                   tau,
    const double                   allowance,
    SymmetricTensor<2, dim>       &sigma,
    SymmetricTensor<4, dim>       *tangent,
    SymmetricTensor<2, dim>       *fracture) const
  {
    // The cone shifted by the allowance: s sigma - allowance I in the cone
    // is the unshifted barrier at the strain less C^{-1} allowance I.
    const double G2 = 2 * shear;
    const auto e = spectrum<dim>(sign * eps - allowance / (G2 + dim * lambda) *
                                                unit_symmetric_tensor<dim>());
    const double beta = lambda / (G2 + dim * lambda);
    // With A = (I - beta 1 1^T) / 2G the stationarity A s - e - tau / s = 0
    // reads s_i / 2G - tau / s_i = e_i + beta T / 2G, T = sum_j s_j: each
    // s_i is the negative root of a quadratic in the trace T, and T solves
    // one increasing scalar equation (Newton's method, from T = 0).
    std::array<double, dim> s{}, ds{};
    const auto              roots = [&](const double T) {
      double sum = 0, slope = 0;
      for (unsigned int i = 0; i < dim; ++i)
        {
          const double x = G2 * (e[i].first + beta * T / G2);
          const double r = std::sqrt(x * x + 4 * G2 * tau);
          // Without cancellation where the direction is open (x > 0).
          s[i] = x < 0 ? 0.5 * (x - r) : -2 * G2 * tau / (x + r);
          ds[i] =
            0.5 * beta * (x < 0 ? 1 - x / r : 4 * G2 * tau / ((x + r) * r));
          sum += s[i];
          slope += ds[i];
        }
      return std::make_pair(T - sum, 1 - slope);
    };
    double T = 0;
    for (unsigned int it = 0; it < 50; ++it)
      {
        const auto [f, df] = roots(T);
        const double step  = f / df;
        T -= step;
        if (std::abs(step) <= 1e-15 * (std::abs(T) + std::sqrt(G2 * tau)))
          break;
      }
    roots(T);
    // d s / d e = H^{-1}, H = diag(1/2G + tau / s_i^2) - beta / 2G 1 1^T
    // (Sherman-Morrison).
    std::array<double, dim> d{};
    double                  sum_d = 0;
    for (unsigned int i = 0; i < dim; ++i)
      {
        d[i] = 1. / (1. / G2 + tau / (s[i] * s[i]));
        sum_d += d[i];
      }
    const double c = (beta / G2) / (1 - (beta / G2) * sum_d);
    const auto   J = [&](const unsigned int i, const unsigned int j) {
      return (i == j ? d[i] : 0.) + c * d[i] * d[j];
    };
    std::array<SymmetricTensor<2, dim>, dim> N;
    for (unsigned int i = 0; i < dim; ++i)
      N[i] = symmetrize(outer_product(e[i].second, e[i].second));
    sigma = 0;
    for (unsigned int i = 0; i < dim; ++i)
      sigma += (s[i] + allowance) * N[i];
    sigma *= sign;
    if (fracture)
      {
        *fracture = 0;
        for (unsigned int i = 0; i < dim; ++i)
          *fracture += (-tau / s[i]) * N[i];
        *fracture *= sign;
      }
    if (!tangent)
      return;
    // The principal derivatives, then the spins.
    *tangent     = 0;
    double scale = 0;
    for (unsigned int i = 0; i < dim; ++i)
      scale = std::max(scale, std::abs(e[i].first));
    for (unsigned int j = 0; j < dim; ++j)
      for (unsigned int k = 0; k < dim; ++k)
        *tangent += J(j, k) * outer_product(N[j], N[k]);
    // Where two strains coincide, the limit of the divided difference.
    add_spins<dim>(e,
                   s,
                   1e-8 * scale,
                   *tangent,
                   [&](const unsigned int i, const unsigned int j) {
                     return J(i, i) - J(i, j);
                   });
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
