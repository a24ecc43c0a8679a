#ifndef hrcontact_stress_constraint_h
#define hrcontact_stress_constraint_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * A convex cone K of admissible stresses (Material/Admissible stresses),
   * imposed on top of the material law: no tension (sigma negative
   * semidefinite, masonry) or no compression (positive semidefinite,
   * membranes). Its multipliers are inelastic strains in the polar cone (the
   * fracture, crack-opening, strains of a no-tension body), and it is
   * regularised by the paper's consistent augmented Lagrangian (eq. 25-26)
   * with the scalar max() replaced by the projection onto that polar cone:
   * at a point with multiplier mu and penalty alpha (a compliance) the
   * complementary energy gains
   *
   *   (|P(mu + alpha sigma)|^2 - |mu|^2) / (2 alpha),
   *
   * C^1 and convex in sigma, whose gradient P(mu + alpha sigma) adds to the
   * strain and whose Hessian alpha DP adds to the compliance; the
   * multiplier update (eq. 48) is mu <- P(mu + alpha sigma). At the fixed
   * point mu = P(mu + alpha sigma): mu in the polar cone, sigma in K and
   * mu : sigma = 0 (doc/materials.md).
   *
   * Each cone registers itself by name with StressConstraintFactory.
   */
  template <int dim>
  class StressConstraint
  {
  public:
    virtual ~StressConstraint() = default;

    /** The name Material/Admissible stresses gives it. */
    virtual std::string
    name() const = 0;

    /** P(X): the projection of X onto the cone of multipliers. */
    virtual dealii::SymmetricTensor<2, dim>
    project(const dealii::SymmetricTensor<2, dim> &X) const = 0;

    /**
     * DP(X)[H]: the derivative of the projection at X in the direction H
     * (symmetric, between 0 and the identity: the added compliance is
     * positive semidefinite).
     */
    virtual dealii::SymmetricTensor<2, dim>
    project_derivative(const dealii::SymmetricTensor<2, dim> &X,
                       const dealii::SymmetricTensor<2, dim> &H) const = 0;

    /**
     * P(X) and DP(X)[H_k] for several directions at once: what the
     * assembler needs at each constraint point (one per stress basis
     * tensor). By default the two calls above; a cone whose projection
     * needs a spectral decomposition computes it once here.
     */
    virtual void
    linearise(const dealii::SymmetricTensor<2, dim>              &X,
              const std::vector<dealii::SymmetricTensor<2, dim>> &H,
              dealii::SymmetricTensor<2, dim>                    &P,
              std::vector<dealii::SymmetricTensor<2, dim>>       &DP) const
    {
      P = project(X);
      DP.resize(H.size());
      for (unsigned int k = 0; k < H.size(); ++k)
        DP[k] = project_derivative(X, H[k]);
    }

    /**
     * How far sigma is from K: the largest principal stress of the wrong
     * sign (0 inside K), in stress units.
     */
    virtual double
    violation(const dealii::SymmetricTensor<2, dim> &sigma) const = 0;

    /** The size of a multiplier: its largest principal value in magnitude. */
    virtual double
    opening(const dealii::SymmetricTensor<2, dim> &mu) const = 0;

    /**
     * The cone imposed at one point in closed form (GaussPointCone): the
     * stress of the strain eps in an isotropic elastic body whose stresses
     * must lie in K, sigma = argmin over K of |sigma - C eps| in the
     * compliance metric (the point's share of eq. 22 maximised over K), C
     * given by its in-plane Lame constants lambda and shear. Also the
     * fracture strain mu = eps - C^{-1} sigma (in the polar cone, mu :
     * sigma = 0) and the derivative d sigma / d eps (the consistent
     * tangent: positive semidefinite, C where no crack is open), each when
     * asked for. The default refuses: a cone without a closed form.
     */
    virtual void
    elastic_projection(const dealii::SymmetricTensor<2, dim> &eps,
                       const double                           lambda,
                       const double                           shear,
                       dealii::SymmetricTensor<2, dim>       &sigma,
                       dealii::SymmetricTensor<4, dim>       *tangent,
                       dealii::SymmetricTensor<2, dim>       *fracture) const;

    /** Whether elastic_projection and barrier_projection are implemented
     * (Method = automatic takes the interior point only then). */
    virtual bool
    has_closed_form() const
    {
      return false;
    }

    /**
     * The cone's log-barrier smoothing at one point (Method = interior
     * point): the stress of the strain eps when the complementary energy
     * of the point gains -tau log det(allowance I - s sigma) (s = +1 for
     * no tension), the cone shifted by @p allowance of wrong-sign stress:
     * sigma = argmax of sigma : eps - sigma : C^{-1} sigma / 2 + tau log
     * det(allowance I - s sigma). Strictly inside the shifted cone, smooth,
     * with a positive definite tangent; the fracture strain mu = eps -
     * C^{-1} sigma meets (s sigma - allowance I)(s mu) = -tau I, missing
     * complementarity by tau per direction (the duality gap). tau,
     * allowance -> 0 give elastic_projection. The default refuses, like
     * elastic_projection.
     */
    virtual void
    barrier_projection(const dealii::SymmetricTensor<2, dim> &eps,
                       const double                           lambda,
                       const double                           shear,
                       const double                           tau,
                       const double                           allowance,
                       dealii::SymmetricTensor<2, dim>       &sigma,
                       dealii::SymmetricTensor<4, dim>       *tangent,
                       dealii::SymmetricTensor<2, dim>       *fracture) const;
  };

  /**
   * The name -> factory registry of stress constraints and the entry
   * Material/Admissible stresses ("any": none, the default).
   */
  template <int dim>
  class StressConstraintFactory
  {
  public:
    using Factory = std::function<std::unique_ptr<StressConstraint<dim>>()>;

    static bool
    register_constraint(const std::string &name, const Factory &factory);

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** The constraint the entry names, or null for "any". */
    static std::unique_ptr<StressConstraint<dim>>
    create(dealii::ParameterHandler &prm);

  private:
    struct Entry
    {
      std::string name;
      Factory     factory;
    };
    static std::vector<Entry> &
    registry();
  };
} // namespace hrcontact

#endif
