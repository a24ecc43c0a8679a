#include <deal.II/base/utilities.h>

#include <hrcontact/material/material_law.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::vector<typename MaterialLawFactory<dim>::Entry> &
  MaterialLawFactory<dim>::registry()
  {
    // Function-local: filled by static initialisers of other files.
    static std::vector<Entry> entries;
    return entries;
  }

  template <int dim>
  bool
  MaterialLawFactory<dim>::register_law(
    const std::string                             &name,
    const std::function<void(ParameterHandler &)> &declare,
    const Factory                                 &factory)
  {
    for (const Entry &e : registry())
      AssertThrow(e.name != name,
                  ExcMessage("material law '" + name +
                             "' is registered twice"));
    registry().push_back({name, declare, factory});
    return true;
  }

  template <int dim>
  void
  MaterialLawFactory<dim>::declare_parameters(ParameterHandler &prm)
  {
    std::string names;
    for (const Entry &e : registry())
      names += (names.empty() ? "" : ", ") + e.name;
    prm.enter_subsection("Material");
    prm.declare_entry("Model",
                      "linear elasticity",
                      Patterns::Anything(),
                      "The material law, by name: " + names +
                        ". Each reads its own entries of this subsection.");
    prm.leave_subsection();
    for (const Entry &e : registry())
      e.declare(prm);
  }

  template <int dim>
  std::unique_ptr<MaterialLaw<dim>>
  MaterialLawFactory<dim>::create(ParameterHandler &prm,
                                  const Constants  &constants)
  {
    prm.enter_subsection("Material");
    const std::string name = Utilities::trim(prm.get("Model"));
    prm.leave_subsection();
    for (const Entry &e : registry())
      if (e.name == name)
        {
          std::unique_ptr<MaterialLaw<dim>> law = e.factory();
          law->parse_parameters(prm, constants);
          return law;
        }
    std::string names;
    for (const Entry &e : registry())
      names += (names.empty() ? "" : ", ") + e.name;
    throw InputError("Material/Model: unknown material law '" + name +
                     "' (known: " + names + ").");
  }

  template <int dim>
  SymmetricTensor<4, dim>
  compliance_tensor(const MaterialLaw<dim>        &law,
                    const SymmetricTensor<2, dim> &sigma,
                    const Point<dim>              &x)
  {
    SymmetricTensor<4, dim> C;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = k; l < dim; ++l)
        {
          // tau with ones at (k, l) and (l, k): C : tau = 2 C_ijkl off the
          // diagonal.
          SymmetricTensor<2, dim> tau;
          tau[k][l]                       = 1;
          const SymmetricTensor<2, dim> c = law.compliance_times(sigma, tau, x);
          const double                  scale = (k == l) ? 1. : 0.5;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              C[i][j][k][l] = scale * c[i][j];
        }
    return C;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  stress_at_strain(const MaterialLaw<dim>        &law,
                   const SymmetricTensor<2, dim> &eps,
                   const Point<dim>              &x,
                   const SymmetricTensor<2, dim> *start)
  {
    SymmetricTensor<2, dim> s =
      start ?
        *start :
        invert(compliance_tensor(law, SymmetricTensor<2, dim>(), x)) * eps;
    double misfit = (law.strain(s, x) - eps).norm();
    for (unsigned int step = 0; step < 50; ++step)
      {
        if (misfit <= 1e-14 * eps.norm() || misfit == 0)
          return s;
        const SymmetricTensor<2, dim> ds =
          invert(compliance_tensor(law, s, x)) * (law.strain(s, x) - eps);
        double length = 1;
        for (unsigned int halving = 0; halving < 30; ++halving, length /= 2)
          {
            const double m = (law.strain(s - length * ds, x) - eps).norm();
            if (m < misfit || halving == 29)
              {
                s -= length * ds;
                misfit = m;
                break;
              }
          }
      }
    if (misfit <= 1e-10 * eps.norm())
      return s;
    throw NotConvergedError("inverting the material law for the stress of a "
                            "strain did not converge in 50 Newton steps.");
  }

  template SymmetricTensor<4, 2>
  compliance_tensor(const MaterialLaw<2> &,
                    const SymmetricTensor<2, 2> &,
                    const Point<2> &);
  template SymmetricTensor<4, 3>
  compliance_tensor(const MaterialLaw<3> &,
                    const SymmetricTensor<2, 3> &,
                    const Point<3> &);
  template SymmetricTensor<2, 2>
  stress_at_strain(const MaterialLaw<2> &,
                   const SymmetricTensor<2, 2> &,
                   const Point<2> &,
                   const SymmetricTensor<2, 2> *);
  template SymmetricTensor<2, 3>
  stress_at_strain(const MaterialLaw<3> &,
                   const SymmetricTensor<2, 3> &,
                   const Point<3> &,
                   const SymmetricTensor<2, 3> *);

  template class MaterialLawFactory<2>;
  template class MaterialLawFactory<3>;
} // namespace hrcontact
