#ifndef hrcontact_linear_elasticity_h
#define hrcontact_linear_elasticity_h

#include <hrcontact/material/material_law.h>

namespace hrcontact
{
  /**
   * Material law "linear elasticity": isotropic, phi^c(sigma) = sigma : E^{-1}
   * sigma / 2 with Young's modulus E and Poisson's ratio nu; in 2D plane
   * strain (eps_zz = 0: E' = E/(1 - nu^2), nu' = nu/(1 - nu) in the in-plane
   * compliance, sigma_zz = nu (sxx + syy)) or plane stress (sigma_zz = 0).
   */
  template <int dim>
  class LinearElasticity : public MaterialLaw<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants) override;

    dealii::SymmetricTensor<2, dim>
    strain(const dealii::SymmetricTensor<2, dim> &sigma,
           const dealii::Point<dim>              &x) const override;
    dealii::SymmetricTensor<2, dim>
    compliance_times(const dealii::SymmetricTensor<2, dim> &sigma,
                     const dealii::SymmetricTensor<2, dim> &tau,
                     const dealii::Point<dim>              &x) const override;
    /** sigma : E^{-1} sigma / 2. */
    double
    complementary_energy(const dealii::SymmetricTensor<2, dim> &sigma,
                         const dealii::Point<dim> &x) const override
    {
      return 0.5 * (sigma * strain(sigma, x));
    }

    bool
    is_linear() const override;
    /** E and nu are constants. */
    bool
    is_homogeneous() const override;
    /** (1 - nu^2)/E in plane strain, 1/E in plane stress, 1/(E h) in 3D
     * with h the mean cell size (volume / cells)^(1/3). */
    double
    nodal_compliance(
      const dealii::Triangulation<dim> &triangulation) const override;
    double
    out_of_plane_stress(
      const dealii::SymmetricTensor<2, dim> &sigma) const override;
    std::string
    plane_condition_name() const override;
    /** Itself. */
    const LinearElasticity<dim> *
    elastic_part() const override
    {
      return this;
    }

    double
    youngs_modulus() const
    {
      return E;
    }
    double
    poisson_ratio() const
    {
      return nu;
    }
    bool
    is_plane_strain() const
    {
      return plane_strain;
    }

  private:
    /** E^{-1} tau (plane strain with E', nu'). */
    dealii::SymmetricTensor<2, dim>
    strain_from_stress(const dealii::SymmetricTensor<2, dim> &tau) const;

    double E            = 1;
    double nu           = 0;
    bool   plane_strain = true;
  };
} // namespace hrcontact

#endif
