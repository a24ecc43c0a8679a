#include <deal.II/base/utilities.h>

#include <hrcontact/core/input.h>
#include <hrcontact/material/stress_constraint.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  StressConstraint<dim>::elastic_projection(const SymmetricTensor<2, dim> &,
                                            const double,
                                            const double,
                                            SymmetricTensor<2, dim> &,
                                            SymmetricTensor<4, dim> *,
                                            SymmetricTensor<2, dim> *) const
  {
    throw InputError("Material/Admissible stresses = " + name() +
                     ": this cone has no closed-form projection; set Stress "
                     "constraint iteration/Method = augmented Lagrangian.");
  }

  template <int dim>
  void
  StressConstraint<dim>::barrier_projection(const SymmetricTensor<2, dim> &,
                                            const double,
                                            const double,
                                            const double,
                                            const double,
                                            SymmetricTensor<2, dim> &,
                                            SymmetricTensor<4, dim> *,
                                            SymmetricTensor<2, dim> *) const
  {
    throw InputError("Material/Admissible stresses = " + name() +
                     ": this cone has no barrier; set Stress constraint "
                     "iteration/Method = augmented Lagrangian.");
  }

  template <int dim>
  std::vector<typename StressConstraintFactory<dim>::Entry> &
  StressConstraintFactory<dim>::registry()
  {
    // Function-local: filled by static initialisers of other files.
    static std::vector<Entry> entries;
    return entries;
  }

  template <int dim>
  bool
  StressConstraintFactory<dim>::register_constraint(const std::string &name,
                                                    const Factory     &factory)
  {
    for (const Entry &e : registry())
      AssertThrow(e.name != name,
                  ExcMessage("stress constraint '" + name +
                             "' is registered twice"));
    registry().push_back({name, factory});
    return true;
  }

  template <int dim>
  void
  StressConstraintFactory<dim>::declare_parameters(ParameterHandler &prm)
  {
    std::string names = "any";
    for (const Entry &e : registry())
      names += ", " + e.name;
    prm.enter_subsection("Material");
    prm.declare_entry(
      "Admissible stresses",
      "any",
      Patterns::Anything(),
      "A cone the stresses must lie in, on top of the law: " + names +
        ". 'no tension' (masonry: no positive principal stress) and 'no "
        "compression' (membranes: no negative one) are imposed by the "
        "consistent augmented Lagrangian at the points that subsection "
        "Stress constraint iteration names (the cell vertices by default), "
        "with the fracture strains as multipliers. 'any' adds nothing.");
    prm.leave_subsection();
  }

  template <int dim>
  std::unique_ptr<StressConstraint<dim>>
  StressConstraintFactory<dim>::create(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    const std::string name = Utilities::trim(prm.get("Admissible stresses"));
    prm.leave_subsection();
    if (name == "any")
      return nullptr;
    for (const Entry &e : registry())
      if (e.name == name)
        return e.factory();
    std::string names = "any";
    for (const Entry &e : registry())
      names += ", " + e.name;
    throw InputError("Material/Admissible stresses: unknown constraint '" +
                     name + "' (known: " + names + ").");
  }

  template class StressConstraint<2>;
  template class StressConstraint<3>;
  template class StressConstraintFactory<2>;
  template class StressConstraintFactory<3>;
} // namespace hrcontact
