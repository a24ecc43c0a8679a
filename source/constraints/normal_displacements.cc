#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/normal_displacements.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

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

  template <int dim>
  std::string
  NormalDisplacements<dim>::entry() const
  {
    return "Supports/Normal displacements";
  }

  template <int dim>
  bool
  NormalDisplacements<dim>::acts_on(const types::boundary_id id) const
  {
    return values.count(id) > 0;
  }

  template <int dim>
  bool
  NormalDisplacements<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection("Supports");
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get("Normal displacements"),
                             dim,
                             false,
                             "Supports/Normal displacements"))
      {
        const std::string where = "Supports/Normal displacements, boundary " +
                                  std::to_string(e.boundary_id);
        (void)earlier;
        values[e.boundary_id] =
          make_function<dim>(e.expressions, 1, constants, where);
      }
    prm.leave_subsection();
    return !values.empty();
  }

  template <int dim>
  void
  NormalDisplacements<dim>::collect(
    const BoundaryFace<dim>           &face,
    const EquilibriumSystem           &system,
    std::vector<NodeConstraints<dim>> &nodes) const
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
        if (c.has_normal && c.normal_is_unilateral != false)
          throw InputError("Supports: " + system.describe_node(node) +
                           " has both a bilateral normal constraint and a "
                           "unilateral boundary support.");
        c.has_normal           = true;
        c.normal_is_unilateral = false;
        if (!std::isfinite(c.gap))
          throw InputError(
            "Supports/Normal displacements: the value for boundary " +
            std::to_string(face.boundary_id) + " is not finite at " +
            system.describe_node(node) + ".");
      }
  }

  template class NormalDisplacements<2>;
  template class NormalDisplacements<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(NormalDisplacements, 20)
} // namespace hrcontact
