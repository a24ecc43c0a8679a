#ifndef hrcontact_normal_displacements_h
#define hrcontact_normal_displacements_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>

namespace hrcontact
{
  /**
   * Supports/Normal displacements: bilateral constraints u.n = g along the
   * body's outward normal (face normals averaged at a node), Q rows of eq.
   * 38 held at their value.
   */
  template <int dim>
  class NormalDisplacements : public ConstraintSource<dim>
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
      values;
  };
} // namespace hrcontact

#endif
