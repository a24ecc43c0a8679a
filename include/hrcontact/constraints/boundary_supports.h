#ifndef hrcontact_boundary_supports_h
#define hrcontact_boundary_supports_h

#include <hrcontact/constraints/normal_displacements.h>

namespace hrcontact
{
  /**
   * Contact/Boundary supports: unilateral frictionless supports along the
   * body's own boundary against a rigid surrounding medium (the ground
   * around a tunnel lining): u.n - g <= 0 with n the body's outward normal
   * at the node and g the initial gap.
   */
  template <int dim>
  class BoundarySupports : public BodyNormalConstraint<dim>
  {
  public:
    BoundarySupports();
    static void
    declare_parameters(dealii::ParameterHandler &prm);
  };
} // namespace hrcontact

#endif
