#include <hrcontact/material/ramberg_osgood.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** A plane-stress tensor as the 3D one it stands for (sigma_zz = 0). */
    template <int dim>
    SymmetricTensor<2, 3>
    as_3d(const SymmetricTensor<2, dim> &t)
    {
      SymmetricTensor<2, 3> t3;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          t3[i][j] = t[i][j];
      return t3;
    }

    /** The in-plane part of a 3D tensor (all of it in 3D). */
    template <int dim>
    SymmetricTensor<2, dim>
    in_plane(const SymmetricTensor<2, 3> &t3)
    {
      SymmetricTensor<2, dim> t;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          t[i][j] = t3[i][j];
      return t;
    }
  } // namespace

  template <int dim>
  void
  RambergOsgood<dim>::declare_parameters(ParameterHandler &prm)
  {
    // The elastic part's entries, declared as LinearElasticity declares them
    // (declaring an entry again with the same text changes nothing).
    LinearElasticity<dim>::declare_parameters(prm);
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Ramberg-Osgood coefficient",
                        "0",
                        Patterns::Anything(),
                        "Ramberg-Osgood: the coefficient a of the power law "
                        "eps = sigma/E (1 + a |sigma/sigma_0|^(n-1)) in "
                        "uniaxial stress (an expression of constants); >= 0.");
      prm.declare_entry("Ramberg-Osgood reference stress",
                        "1",
                        Patterns::Anything(),
                        "Ramberg-Osgood: the reference stress sigma_0 (an "
                        "expression of constants); > 0.");
      prm.declare_entry("Ramberg-Osgood exponent",
                        "1",
                        Patterns::Anything(),
                        "Ramberg-Osgood: the hardening exponent n (an "
                        "expression of constants); >= 1, where the "
                        "complementary potential is convex.");
    }
    prm.leave_subsection();
  }

  template <int dim>
  void
  RambergOsgood<dim>::parse_parameters(ParameterHandler &prm,
                                       const Constants  &constants)
  {
    elastic.parse_parameters(prm, constants);
    if (dim == 2 && elastic.is_plane_strain())
      throw InputError(
        "Material/Model = Ramberg-Osgood needs Material/Plane condition = "
        "plane stress in 2D: in plane strain sigma_zz would solve a nonlinear "
        "equation at every point.");
    prm.enter_subsection("Material");
    {
      a = evaluate_constant_expression(prm.get("Ramberg-Osgood coefficient"),
                                       constants,
                                       "Material/Ramberg-Osgood coefficient");
      sigma_0 = evaluate_constant_expression(
        prm.get("Ramberg-Osgood reference stress"),
        constants,
        "Material/Ramberg-Osgood reference stress");
      n = evaluate_constant_expression(prm.get("Ramberg-Osgood exponent"),
                                       constants,
                                       "Material/Ramberg-Osgood exponent");
    }
    prm.leave_subsection();
    if (!(a >= 0) || !std::isfinite(a))
      throw InputError("Material/Ramberg-Osgood coefficient must be >= 0 "
                       "(got " +
                       std::to_string(a) + ").");
    if (!(sigma_0 > 0) || !std::isfinite(sigma_0))
      throw InputError("Material/Ramberg-Osgood reference stress must be "
                       "positive (got " +
                       std::to_string(sigma_0) + ").");
    if (!(n >= 1) || !std::isfinite(n))
      throw InputError("Material/Ramberg-Osgood exponent must be >= 1 (got " +
                       std::to_string(n) +
                       "): below 1 the complementary potential is not convex.");
  }

  template <int dim>
  double
  RambergOsgood<dim>::equivalent_stress(const SymmetricTensor<2, dim> &sigma)
  {
    const SymmetricTensor<2, 3> s = deviator(as_3d(sigma));
    return std::sqrt(1.5 * (s * s));
  }

  template <int dim>
  SymmetricTensor<2, dim>
  RambergOsgood<dim>::strain(const SymmetricTensor<2, dim> &sigma,
                             const Point<dim>              &x) const
  {
    SymmetricTensor<2, dim> eps = elastic.strain(sigma, x);
    const double            eq  = equivalent_stress(sigma);
    if (a == 0 || eq == 0)
      return eps;
    const double E = elastic.youngs_modulus();
    const double g = 1.5 * a / E * std::pow(eq / sigma_0, n - 1);
    return eps + g * in_plane<dim>(deviator(as_3d(sigma)));
  }

  template <int dim>
  double
  RambergOsgood<dim>::complementary_energy(const SymmetricTensor<2, dim> &sigma,
                                           const Point<dim> &x) const
  {
    const double eq = equivalent_stress(sigma);
    return elastic.complementary_energy(sigma, x) +
           a * sigma_0 * sigma_0 / (elastic.youngs_modulus() * (n + 1)) *
             std::pow(eq / sigma_0, n + 1);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  RambergOsgood<dim>::compliance_times(const SymmetricTensor<2, dim> &sigma,
                                       const SymmetricTensor<2, dim> &tau,
                                       const Point<dim>              &x) const
  {
    SymmetricTensor<2, dim> d_eps = elastic.compliance_times(sigma, tau, x);
    if (a == 0)
      return d_eps;
    const double E  = elastic.youngs_modulus();
    const double eq = equivalent_stress(sigma);
    if (n == 1)
      return d_eps + 1.5 * a / E * in_plane<dim>(deviator(as_3d(tau)));
    // The power term's Hessian vanishes at sigma_eq = 0 for n > 1.
    if (eq == 0)
      return d_eps;
    const SymmetricTensor<2, 3> s = deviator(as_3d(sigma));
    const SymmetricTensor<2, 3> t = as_3d(tau);
    const double                g = 1.5 * a / E * std::pow(eq / sigma_0, n - 1);
    return d_eps + g * in_plane<dim>(deviator(t) +
                                     1.5 * (n - 1) * (s * t) / (eq * eq) * s);
  }

  template <int dim>
  bool
  RambergOsgood<dim>::is_linear() const
  {
    return a == 0 || n == 1;
  }

  template <int dim>
  bool
  RambergOsgood<dim>::is_homogeneous() const
  {
    return is_linear();
  }

  template <int dim>
  double
  RambergOsgood<dim>::nodal_compliance(
    const Triangulation<dim> &triangulation) const
  {
    return elastic.nodal_compliance(triangulation);
  }

  template <int dim>
  double
  RambergOsgood<dim>::out_of_plane_stress(const SymmetricTensor<2, dim> &) const
  {
    return 0;
  }

  template <int dim>
  std::string
  RambergOsgood<dim>::plane_condition_name() const
  {
    return elastic.plane_condition_name();
  }

  template class RambergOsgood<2>;
  template class RambergOsgood<3>;

  HRCONTACT_REGISTER_MATERIAL_LAW(RambergOsgood, "Ramberg-Osgood")
} // namespace hrcontact
