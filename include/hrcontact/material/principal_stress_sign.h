#ifndef hrcontact_principal_stress_sign_h
#define hrcontact_principal_stress_sign_h

#include <hrcontact/material/stress_constraint.h>

namespace hrcontact
{
  /**
   * Stress constraints "no tension" (every principal stress <= 0: masonry,
   * unreinforced concrete, rock joints; the multipliers are positive
   * semidefinite fracture strains) and "no compression" (every principal
   * stress >= 0: membranes, cable-like regions; negative semidefinite
   * multipliers, wrinkling strains). One class: the second is the first
   * with a sign, P(X) = s P_+(s X), DP(X)[H] = DP_+(s X)[H].
   *
   * The projection onto the positive semidefinite cone keeps the positive
   * part of the spectrum, P_+(X) = sum_i max(lambda_i, 0) n_i n_i; its
   * derivative (Loewner's divided differences) is
   *
   *   DP_+(X)[H] = sum_ij theta_ij (n_i . H n_j) n_i n_j,
   *   theta_ij = (lambda_i^+ - lambda_j^+) / (lambda_i - lambda_j),
   *
   * 1 where both are positive, 0 where neither is. In 2D the tensor is the
   * in-plane stress: in plane strain the cracks are in-plane (the fracture
   * strain has no zz part), so sigma_zz = nu (sigma_xx + sigma_yy) stays
   * <= 0 when the in-plane stresses are admissible, and the three
   * dimensional condition holds; in plane stress sigma_zz = 0.
   */
  template <int dim>
  class PrincipalStressSign : public StressConstraint<dim>
  {
  public:
    /** +1: no tension, -1: no compression. */
    explicit PrincipalStressSign(const double sign);

    std::string
    name() const override;
    bool
    has_closed_form() const override
    {
      return true;
    }
    dealii::SymmetricTensor<2, dim>
    project(const dealii::SymmetricTensor<2, dim> &X) const override;
    dealii::SymmetricTensor<2, dim>
    project_derivative(const dealii::SymmetricTensor<2, dim> &X,
                       const dealii::SymmetricTensor<2, dim> &H) const override;
    /** One spectral decomposition of s X for P and every DP[H_k]. */
    void
    linearise(const dealii::SymmetricTensor<2, dim>              &X,
              const std::vector<dealii::SymmetricTensor<2, dim>> &H,
              dealii::SymmetricTensor<2, dim>                    &P,
              std::vector<dealii::SymmetricTensor<2, dim>> &DP) const override;
    double
    violation(const dealii::SymmetricTensor<2, dim> &sigma) const override;
    double
    opening(const dealii::SymmetricTensor<2, dim> &mu) const override;
    /**
     * In the principal frame of s eps (e_1 >= ... >= e_dim), the cracks
     * open along the m largest strains: sigma_i = 0 there, mu_i = e_i +
     * lambda tr / (2 G), and sigma_j = lambda tr + 2 G e_j elsewhere, with
     * tr = (sum_j e_j) 2 G / (2 G + m lambda) the trace of the elastic
     * strain. The first m = 0, ..., dim whose sigma_j <= 0 and mu_i >= 0
     * is the projection (a point that meets them is the KKT point of a
     * strictly convex problem). The tangent is that of an isotropic
     * function of the strain: the derivatives of the principal stresses
     * plus the spins (sigma_i - sigma_j) / (e_i - e_j); no compression is
     * the mirror, sigma(eps) = -sigma_+(-eps).
     */
    void
    elastic_projection(
      const dealii::SymmetricTensor<2, dim> &eps,
      const double                           lambda,
      const double                           shear,
      dealii::SymmetricTensor<2, dim>       &sigma,
      dealii::SymmetricTensor<4, dim>       *tangent,
      dealii::SymmetricTensor<2, dim>       *fracture) const override;
    /**
     * In the principal frame of s eps (less C^{-1} allowance I) the
     * barrier stress is coaxial with it: its shifted principal values s_i
     * < 0 minimise s.A s / 2 - e.s - tau sum_i log(-s_i) (A = C^{-1} in the
     * frame). Each s_i is the negative root of a quadratic in the trace,
     * which solves one increasing scalar equation (Newton's method), and
     * mu_i = tau / (-s_i). The tangent is the inverse Hessian on the
     * principal values (Sherman-Morrison) plus the spins, as for
     * elastic_projection.
     */
    void
    barrier_projection(
      const dealii::SymmetricTensor<2, dim> &eps,
      const double                           lambda,
      const double                           shear,
      const double                           tau,
      const double                           allowance,
      dealii::SymmetricTensor<2, dim>       &sigma,
      dealii::SymmetricTensor<4, dim>       *tangent,
      dealii::SymmetricTensor<2, dim>       *fracture) const override;

  private:
    const double sign;
  };
} // namespace hrcontact

#endif
