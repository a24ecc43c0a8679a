#include <hrcontact/constraints/boundary_supports.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  BoundarySupports<dim>::BoundarySupports()
    : BodyNormalConstraint<dim>("Contact",
                                "Boundary supports",
                                true,
                                "a normal constraint or an obstacle")
  {}

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

  template class BoundarySupports<2>;
  template class BoundarySupports<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(BoundarySupports, 40)
} // namespace hrcontact
