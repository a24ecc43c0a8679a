#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/prescribed_displacements.h>

#include <cmath>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  PrescribedDisplacements<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Supports");
    prm.declare_entry(
      "Prescribed displacements",
      "",
      Patterns::Anything(),
      "Prescribed displacement components (the H rows) per boundary id: "
      "'id [components]: values', entries separated by '|'. Components are "
      "letters x, y, z (all if omitted), with one expression per named "
      "component, e.g. '0: 0; 0 | 2 y: -1e-3'. Where two ids meet, their "
      "values must agree.");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  PrescribedDisplacements<dim>::entry() const
  {
    return "Supports/Prescribed displacements";
  }

  template <int dim>
  bool
  PrescribedDisplacements<dim>::acts_on(const types::boundary_id id) const
  {
    return prescriptions.count(id) > 0;
  }

  template <int dim>
  std::vector<types::boundary_id>
  PrescribedDisplacements<dim>::boundary_ids() const
  {
    return boundary_ids_of(prescriptions);
  }

  template <int dim>
  bool
  PrescribedDisplacements<dim>::is_normal_kind() const
  {
    return false;
  }

  template <int dim>
  bool
  PrescribedDisplacements<dim>::parse_parameters(
    ParameterHandler &prm,
    const Constants  &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &)
  {
    prm.enter_subsection("Supports");
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get("Prescribed displacements"),
                             dim,
                             true,
                             "Supports/Prescribed displacements"))
      {
        Prescription &pd = prescriptions[e.boundary_id];
        pd.components    = e.components;
        pd.values =
          make_function<dim>(e.expressions,
                             e.components.size(),
                             constants,
                             "Supports/Prescribed displacements, boundary " +
                               std::to_string(e.boundary_id));
      }
    prm.leave_subsection();
    return !prescriptions.empty();
  }

  template <int dim>
  double
  PrescribedDisplacements<dim>::prescribed_value(const types::boundary_id id,
                                                 const unsigned int       d,
                                                 const Point<dim> &x) const
  {
    const auto it = prescriptions.find(id);
    if (it != prescriptions.end())
      for (unsigned int k = 0; k < it->second.components.size(); ++k)
        if (it->second.components[k] == d)
          return it->second.values->value(x, k);
    return std::numeric_limits<double>::quiet_NaN();
  }

  template <int dim>
  void
  PrescribedDisplacements<dim>::collect(const BoundaryFace<dim> &face,
                                        const EquilibriumSystem &system,
                                        NodeConstraintMap<dim>  &nodes) const
  {
    const Prescription &pd = prescriptions.at(face.boundary_id);
    for (unsigned int v = 0; v < face.nodes.size(); ++v)
      {
        const unsigned int    node = face.nodes[v];
        const Point<dim>     &x    = face.points[v];
        NodeConstraints<dim> &c    = nodes[node];
        for (unsigned int k = 0; k < pd.components.size(); ++k)
          {
            const unsigned int d     = pd.components[k];
            const double       value = pd.values->value(x, k);
            if (!std::isfinite(value))
              throw InputError(
                "Supports/Prescribed displacements: the value for "
                "boundary " +
                std::to_string(face.boundary_id) + " is not finite at " +
                system.describe_node(node) + ".");
            if (!c.prescribe(d, value))
              throw InputError(
                "Supports/Prescribed displacements: two boundaries "
                "prescribe different values of component " +
                std::string(1, "xyz"[d]) + " at " + system.describe_node(node) +
                ".");
          }
      }
  }

  template class PrescribedDisplacements<2>;
  template class PrescribedDisplacements<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(PrescribedDisplacements, 10)
} // namespace hrcontact
