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

  private:
    const double sign;
  };
} // namespace hrcontact

#endif
