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
