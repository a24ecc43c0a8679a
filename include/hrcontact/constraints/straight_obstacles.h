#ifndef hrcontact_straight_obstacles_h
#define hrcontact_straight_obstacles_h

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>

namespace hrcontact
{
  /**
   * Contact/Obstacles: rigid straight obstacles (a line in 2D, a plane in
   * 3D), a point x0 and the unit normal n into the obstacle; every node of
   * the boundary gets a unilateral row with the gap g = (x0 - x).n (eq. 10,
   * 35). Several obstacles at a node make a corner (eq. 11).
   */
  template <int dim>
  class StraightObstacles : public ConstraintSource<dim>
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

    /** The gap to the plane and the normal displacement are both linear
     * along a straight face. */
    bool
    holds_pointwise_from_nodes() const override
    {
      return true;
    }
    bool
    acts_on(const dealii::types::boundary_id id) const override;
    std::vector<dealii::types::boundary_id>
    boundary_ids() const override;
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;

  private:
    struct Obstacle
    {
      dealii::Point<dim>     point;
      dealii::Tensor<1, dim> normal;
    };
    std::map<dealii::types::boundary_id, Obstacle> obstacles;
  };
} // namespace hrcontact

#endif
