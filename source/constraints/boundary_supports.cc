#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/boundary_supports.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  BoundarySupports<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Boundary supports",
      "",
      Patterns::Anything(),
      "Unilateral frictionless supports along the body's own boundary, "
      "against a rigid surrounding medium (e.g. the ground around a tunnel "
      "lining): 'id: g', entries separated by '|', with g the initial gap "
      "(an expression in x, y (, z); 0 for a medium in contact). Each node "
      "of the boundary gets w.n - g <= 0 with n the outward normal of the "
      "body at the node (face normals averaged), the same constraint as an "
      "obstacle. Empty: none.");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  BoundarySupports<dim>::entry() const
  {
    return "Contact/Boundary supports";
  }

  template <int dim>
  bool
  BoundarySupports<dim>::acts_on(const types::boundary_id id) const
  {
    return gaps.count(id) > 0;
  }

  template <int dim>
  bool
  BoundarySupports<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection("Contact");
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get("Boundary supports"),
                             dim,
                             false,
                             "Contact/Boundary supports"))
      {
        const std::string where = "Contact/Boundary supports, boundary " +
                                  std::to_string(e.boundary_id);
        require_unconstrained<dim>(e.boundary_id,
                                   where,
                                   earlier,
                                   "a normal constraint or an obstacle");
        gaps[e.boundary_id] =
          make_function<dim>(e.expressions, 1, constants, where);
      }
    prm.leave_subsection();
    return !gaps.empty();
  }

  template <int dim>
  void
  BoundarySupports<dim>::collect(const BoundaryFace<dim>           &face,
                                 const EquilibriumSystem           &system,
                                 std::vector<NodeConstraints<dim>> &nodes) const
  {
    // Bilateral normal constraints and unilateral boundary supports share
    // the node normal (area-weighted face normals).
    const FunctionParser<dim> &value = *gaps.at(face.boundary_id);
    for (unsigned int v = 0; v < face.nodes.size(); ++v)
      {
        const unsigned int    node = face.nodes[v];
        NodeConstraints<dim> &c    = nodes[node];
        c.normal_sum += face.normal * face.measure;
        c.face_normals.push_back(face.normal);
        c.gap = value.value(face.points[v]);
        if (c.has_normal && c.normal_is_unilateral != true)
          throw InputError("Supports: " + system.describe_node(node) +
                           " has both a bilateral normal constraint and a "
                           "unilateral boundary support.");
        c.has_normal           = true;
        c.normal_is_unilateral = true;
        if (!std::isfinite(c.gap))
          throw InputError(
            "Contact/Boundary supports: the value for boundary " +
            std::to_string(face.boundary_id) + " is not finite at " +
            system.describe_node(node) + ".");
      }
  }

  template class BoundarySupports<2>;
  template class BoundarySupports<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(BoundarySupports, 40)
} // namespace hrcontact
