#ifndef hrcontact_point_supports_h
#define hrcontact_point_supports_h

#include <deal.II/base/point.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <vector>

namespace hrcontact
{
  /**
   * Supports/Point supports: displacement components fixed at single
   * boundary nodes (H rows, like Prescribed displacements, at one node).
   * Why: a rigid motion is best held at one point where holding a whole
   * boundary would constrain a deformation the answer has (the
   * manufactured no-tension pier's base, whose exact u_x varies along it,
   * doc/materials.md). Each point must be a node of its boundary.
   */
  template <int dim>
  class PointSupports : public ConstraintSource<dim>
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
    bool
    is_normal_kind() const override;
    /** Every point must be a node of a face of its boundary (every process
     * sees the whole boundary here). */
    void
    prepare(const std::vector<BoundaryFace<dim>> &faces,
            const EquilibriumSystem              &system) const override;
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;

  private:
    struct Support
    {
      dealii::Point<dim>        point;
      std::vector<unsigned int> components;
      std::vector<double>       values; // one per component
    };
    /** Whether face vertex @p x is @p point (to 1e-8 of the face's size). */
    static bool
    at(const BoundaryFace<dim>  &face,
       const dealii::Point<dim> &x,
       const dealii::Point<dim> &point);

    std::multimap<dealii::types::boundary_id, Support> supports;
  };
} // namespace hrcontact

#endif
