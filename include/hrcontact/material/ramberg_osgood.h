#ifndef hrcontact_ramberg_osgood_h
#define hrcontact_ramberg_osgood_h

#include <hrcontact/material/linear_elasticity.h>

namespace hrcontact
{
  /**
   * Material law "Ramberg-Osgood": Hencky's deformation theory with a power
   * hardening deviatoric part, given by its convex complementary potential
   *
   *   phi^c(sigma) = sigma : E^{-1} sigma / 2
   *                  + a sigma_0^2 / (E (n + 1)) (sigma_eq / sigma_0)^(n + 1),
   *
   * sigma_eq = sqrt(3/2 s : s), s the deviator of sigma, so that
   *
   *   eps = E^{-1} sigma + 3/2 a (sigma_eq / sigma_0)^(n - 1) s / E
   *
   * (uniaxially eps = sigma/E (1 + a |sigma/sigma_0|^(n - 1))). The strain
   * is explicit in the stress: a stress code evaluates it directly, where a
   * displacement code must invert it at every quadrature point. Convex for
   * a >= 0 and n >= 1; n = 1 or a = 0 is linear. 3D and plane stress
   * (sigma_zz = 0); plane strain is refused, since there sigma_zz would
   * solve a nonlinear equation at every point. The elastic part is
   * LinearElasticity's, with its parameters.
   */
  template <int dim>
  class RambergOsgood : public MaterialLaw<dim>
  {
  public:
    /** LinearElasticity's entries and the three of the power law. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants) override;

    dealii::SymmetricTensor<2, dim>
    strain(const dealii::SymmetricTensor<2, dim> &sigma,
           const dealii::Point<dim>              &x) const override;
    /**
     * The Hessian of phi^c applied to tau: E^{-1} tau + 3/2 a/E
     * (sigma_eq/sigma_0)^(n-1) [dev tau + 3/2 (n-1) (s : tau)/sigma_eq^2 s].
     */
    double
    complementary_energy(const dealii::SymmetricTensor<2, dim> &sigma,
                         const dealii::Point<dim> &x) const override;

    dealii::SymmetricTensor<2, dim>
    compliance_times(const dealii::SymmetricTensor<2, dim> &sigma,
                     const dealii::SymmetricTensor<2, dim> &tau,
                     const dealii::Point<dim>              &x) const override;
    /** a = 0 or n = 1. */
    bool
    is_linear() const override;
    /** Only when linear: otherwise F_c follows each cell's stresses. */
    bool
    is_homogeneous() const override;
    /** The elastic part's: the compliance at zero stress. */
    double
    nodal_compliance(
      const dealii::Triangulation<dim> &triangulation) const override;
    /** 0: plane stress or 3D. */
    double
    out_of_plane_stress(
      const dealii::SymmetricTensor<2, dim> &sigma) const override;
    std::string
    plane_condition_name() const override;
    /** E^-1 sigma: the floor's elastic solve. */
    const LinearElasticity<dim> *
    elastic_part() const override
    {
      return &elastic;
    }

    /** The equivalent (von Mises) stress sqrt(3/2 s : s) of sigma. */
    static double
    equivalent_stress(const dealii::SymmetricTensor<2, dim> &sigma);

  private:
    LinearElasticity<dim> elastic;
    double                a       = 0;
    double                sigma_0 = 1;
    double                n       = 1;
  };
} // namespace hrcontact

#endif
