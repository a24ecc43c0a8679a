#ifndef hrcontact_two_sided_stops_h
#define hrcontact_two_sided_stops_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/constraints/constraint_source.h>

#include <array>
#include <map>
#include <memory>

namespace hrcontact
{
  /**
   * The TwoSidedStop law with its values g-, g+, p0-, p0+, k-, k+ (a null
   * function: 0) evaluated at a point; bad values stop with an error naming
   * `where`. Used by Contact/Stops and by the stops of contact pairs.
   */
  template <int dim>
  std::shared_ptr<const ConstraintLaw>
  two_sided_stop_at(
    const std::array<const dealii::FunctionParser<dim> *, 6> &values,
    const dealii::Point<dim>                                 &point,
    const std::string                                        &where);

  /**
   * Contact/Stops: two-sided stops with limit reactions (section 2.4.2,
   * Fig. 4) on the nodes of a boundary: one row along the direction d with
   * a TwoSidedStop law made of g-, g+, p0-, p0+ (and k-, k+) evaluated at
   * the node.
   */
  template <int dim>
  class TwoSidedStops : public ConstraintSource<dim>
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
    std::vector<dealii::types::boundary_id>
    boundary_ids() const override;
    OwnRow
    own_row(const unsigned int          node,
            const dealii::Point<dim>   &point,
            const NodeConstraints<dim> &constraints,
            const EquilibriumSystem    &system) const override;
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;

  private:
    struct Stop
    {
      dealii::Tensor<1, dim>                       direction;
      std::unique_ptr<dealii::FunctionParser<dim>> values[6];
    };
    std::map<dealii::types::boundary_id, Stop> stops;
  };
} // namespace hrcontact

#endif
