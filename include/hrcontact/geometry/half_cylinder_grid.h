#ifndef hrcontact_half_cylinder_grid_h
#define hrcontact_half_cylinder_grid_h

#include <hrcontact/geometry/mesh_generator.h>

namespace hrcontact
{
  /**
   * Grid "half_cylinder" (2D): the half model of a cylinder of radius R
   * lying on the plane y = -R, the quarter disk x >= 0, y <= 0, graded
   * towards the contact point (0, -R) by a polar map that keeps the circle
   * exact. Along the surface, half of the nodes lie uniformly on the arc of
   * angle phi_c next to the contact point, the spacing then grows smoothly
   * (quadratic map) up to pi/2; the radius r becomes R (1 - (1 - r/R)^q),
   * which thins the layers towards the surface. Arguments 'R : phi_c : q'.
   * Boundary ids: 0 the symmetry plane x = 0, 1 the loaded diameter y = 0,
   * 2 the curved surface.
   */
  template <int dim>
  class HalfCylinderGrid : public MeshGenerator<dim>
  {
  public:
    HalfCylinderGrid(const std::string &arguments, const Constants &constants);
    void
    create(dealii::Triangulation<dim> &triangulation,
           const unsigned int          refinements) const override;
    bool
    create_coarse(dealii::Triangulation<dim> &triangulation) const override;
    /** The grading map. */
    typename MeshGenerator<dim>::VertexMap
    refined_vertex_map() const override;
    std::map<dealii::types::boundary_id, std::string>
    boundary_names() const override;

  private:
    const std::string arguments;
  };
} // namespace hrcontact

#endif
