#ifndef hrcontact_curved_obstacles_h
#define hrcontact_curved_obstacles_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>
#include <utility>

namespace hrcontact
{
  /**
   * Contact/Curved obstacles: rigid curved obstacles, a circle (a cylinder
   * along z in 3D), a sphere, or the region phi < 0 of a level set. Each
   * node of the boundary gets the row of the straight obstacle tangent at
   * the point of the surface nearest to it (the paper's linearised case,
   * eq. 10). With Update curved obstacles, the rows are linearised again at
   * the current configuration between multiplier updates (relinearisation;
   * condensed path only).
   */
  template <int dim>
  class CurvedObstacles : public ConstraintSource<dim>
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
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;
    bool
    changes_rows() const override;
    std::unique_ptr<RowRelinearisation>
    relinearisation(EquilibriumSystem &system) const override;

    /** One obstacle: its shape and the nearest point of its surface. */
    struct CurvedObstacle
    {
      enum class Shape
      {
        circle,
        sphere,
        level_set
      };
      Shape                                        shape = Shape::circle;
      dealii::Point<dim>                           centre;
      double                                       radius = 0;
      std::unique_ptr<dealii::FunctionParser<dim>> phi;

      /**
       * The point of the obstacle's surface nearest to x (exact for a
       * circle or sphere; for a level set, the iteration x <- x - phi
       * grad phi / |grad phi|^2, which ends on the surface and is the
       * nearest point when phi is a distance), and the unit normal there
       * pointing into the obstacle (-grad phi / |grad phi|).
       */
      std::pair<dealii::Point<dim>, dealii::Tensor<1, dim>>
      project(const dealii::Point<dim> &x) const;
    };

  private:
    std::map<dealii::types::boundary_id, CurvedObstacle> obstacles;
    /** Re-linearise after every multiplier update. */
    bool update = true;
  };
} // namespace hrcontact

#endif
