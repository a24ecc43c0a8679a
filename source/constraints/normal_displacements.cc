#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/normal_displacements.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  BodyNormalConstraint<dim>::BodyNormalConstraint(const std::string &subsection,
                                                  const std::string &name,
                                                  const bool         unilateral,
                                                  const std::string &conflict)
    : subsection(subsection)
    , name(name)
    , unilateral(unilateral)
    , conflict(conflict)
  {}

  template <int dim>
  std::string
  BodyNormalConstraint<dim>::entry() const
  {
    return subsection + "/" + name;
  }

  template <int dim>
  bool
  BodyNormalConstraint<dim>::acts_on(const types::boundary_id id) const
  {
    return values.count(id) > 0;
  }

  template <int dim>
  std::vector<types::boundary_id>
  BodyNormalConstraint<dim>::boundary_ids() const
  {
    return boundary_ids_of(values);
  }

  template <int dim>
  bool
  BodyNormalConstraint<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection(subsection);
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get(name), dim, false, entry()))
      {
        const std::string where =
          entry() + ", boundary " + std::to_string(e.boundary_id);
        require_unconstrained<dim>(e.boundary_id, where, earlier, conflict);
        values[e.boundary_id] =
          make_function<dim>(e.expressions, 1, constants, where);
      }
    prm.leave_subsection();
    return !values.empty();
  }

  template <int dim>
  void
  BodyNormalConstraint<dim>::collect(const BoundaryFace<dim> &face,
                                     const EquilibriumSystem &system,
                                     NodeConstraintMap<dim>  &nodes) const
  {
    // Bilateral normal constraints and unilateral boundary supports share
    // the node normal (area-weighted face normals).
    const FunctionParser<dim> &value = *values.at(face.boundary_id);
    for (unsigned int v = 0; v < face.nodes.size(); ++v)
      {
        const unsigned int    node = face.nodes[v];
        NodeConstraints<dim> &c    = nodes[node];
        c.normal_sum += face.normal * face.measure;
        c.face_normals.push_back(face.normal);
        c.gap = value.value(face.points[v]);
        if (c.has_normal && c.normal_is_unilateral != unilateral)
          throw InputError("Supports: " + system.describe_node(node) +
                           " has both a bilateral normal constraint and a "
                           "unilateral boundary support.");
        c.has_normal           = true;
        c.normal_is_unilateral = unilateral;
        if (!std::isfinite(c.gap))
          throw InputError(entry() + ": the value for boundary " +
                           std::to_string(face.boundary_id) +
                           " is not finite at " + system.describe_node(node) +
                           ".");
      }
  }

  template <int dim>
  double
  BodyNormalConstraint<dim>::normal_value(const types::boundary_id id,
                                          const Point<dim>        &x) const
  {
    if (unilateral || values.count(id) == 0)
      return std::numeric_limits<double>::quiet_NaN();
    return values.at(id)->value(x);
  }

  template <int dim>
  NormalDisplacements<dim>::NormalDisplacements()
    : BodyNormalConstraint<dim>("Supports",
                                "Normal displacements",
                                false,
                                "a normal constraint")
  {}

  template <int dim>
  void
  NormalDisplacements<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Supports");
    prm.declare_entry(
      "Normal displacements",
      "",
      Patterns::Anything(),
      "Bilateral constraints u.n = g (the Q rows, eq. 38) per boundary id: "
      "'id: g', entries separated by '|'. n is the outward unit normal of "
      "the body at each boundary node (face normals averaged); the node's "
      "rows are rotated to (n, tangents) and the tangential ones stay free. "
      "Where a node also has prescribed components, the constraint acts on the "
      "free part of the displacement: n_free . u_free = g - n . u-hat, with "
      "n_free the part of n off the prescribed axes (no row if it vanishes).");
    prm.leave_subsection();
  }

  template class BodyNormalConstraint<2>;
  template class BodyNormalConstraint<3>;
  template class NormalDisplacements<2>;
  template class NormalDisplacements<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(NormalDisplacements, 20)
} // namespace hrcontact
