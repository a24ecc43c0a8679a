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

  template class MaterialLawFactory<2>;
  template class MaterialLawFactory<3>;
} // namespace hrcontact
