#ifndef hrcontact_normal_displacements_h
#define hrcontact_normal_displacements_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>
#include <string>

namespace hrcontact
{
  /**
   * A constraint along the body's own outward normal n at each node of a
   * boundary (area-weighted face normals averaged), with a value g per
   * boundary (an expression in x, y (, z)): bilateral, u.n = g, or
   * unilateral, u.n - g <= 0. The node's rows are rotated to (n, tangents)
   * and the tangential ones stay free. The common part of
   * NormalDisplacements and BoundarySupports.
   */
  template <int dim>
  class BodyNormalConstraint : public ConstraintSource<dim>
  {
  public:
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
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;
    /** Bilateral: g; unilateral: NaN (nothing prescribed). */
    double
    normal_value(const dealii::types::boundary_id id,
                 const dealii::Point<dim>        &x) const override;
    /**
     * Bilateral: along a straight face whose normal is an axis, u . n is
     * one Q1 component, met between the nodes where it is at them (the
     * error bound's ContactTractions::not_covered checks the rows' normals,
     * SupportMismatch a g that Q1 cannot meet).
     */
    bool
    holds_pointwise_from_nodes() const override
    {
      return !unilateral;
    }

  protected:
    /** The entry subsection/name, whether it is unilateral, and what an
     * earlier kind on the same boundary is called in the error. */
    BodyNormalConstraint(const std::string &subsection,
                         const std::string &name,
                         const bool         unilateral,
                         const std::string &conflict);

  private:
    const std::string subsection, name;
    const bool        unilateral;
    const std::string conflict;
    std::map<dealii::types::boundary_id,
             std::unique_ptr<dealii::FunctionParser<dim>>>
      values;
  };

  /**
   * Supports/Normal displacements: bilateral constraints u.n = g, Q rows of
   * eq. 38 held at their value.
   */
  template <int dim>
  class NormalDisplacements : public BodyNormalConstraint<dim>
  {
  public:
    NormalDisplacements();
    static void
    declare_parameters(dealii::ParameterHandler &prm);
  };
} // namespace hrcontact

#endif
