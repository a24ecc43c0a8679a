#ifndef hrcontact_boundary_supports_h
#define hrcontact_boundary_supports_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>

namespace hrcontact
{
  /**
   * Contact/Boundary supports: unilateral frictionless supports along the
   * body's own boundary against a rigid surrounding medium (the ground
   * around a tunnel lining): w.n - g <= 0 with n the body's outward normal
   * at the node (face normals averaged) and g the initial gap.
   */
  template <int dim>
  class BoundarySupports : public ConstraintSource<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    bool
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants,
                     const std::vector<std::shared_ptr<ConstraintSource<dim>>>
                       &earlier) override;
    std::string
    entry() const override;
    bool
    acts_on(const dealii::types::boundary_id id) const override;
    void
    collect(const BoundaryFace<dim>           &face,
            const EquilibriumSystem           &system,
            std::vector<NodeConstraints<dim>> &nodes) const override;

  private:
    std::map<dealii::types::boundary_id,
             std::unique_ptr<dealii::FunctionParser<dim>>>
      gaps;
  };
} // namespace hrcontact

#endif
