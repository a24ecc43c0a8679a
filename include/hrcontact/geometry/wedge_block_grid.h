#ifndef hrcontact_wedge_block_grid_h
#define hrcontact_wedge_block_grid_h

#include <hrcontact/geometry/mesh_generator.h>

namespace hrcontact
{
  /**
   * Grid "wedge_block" (2D): a parallelogram with one corner at the origin,
   * edges a = (L_a, 0) and b = L_b (cos theta, sin theta), n_a x n_b cells
   * (deal.II's subdivided_parallelepiped, not reachable by name). Arguments
   * 'L_a : L_b : theta (degrees) : n_a : n_b', expressions of the constants.
   * Boundary ids: 0 the face along b, 1 its opposite, 2 the face along a,
   * 3 its opposite.
   */
  template <int dim>
  class WedgeBlockGrid : public MeshGenerator<dim>
  {
  public:
    WedgeBlockGrid(const std::string &arguments, const Constants &constants);
    std::map<dealii::types::boundary_id, std::string>
    boundary_names() const override;
    void
    create(dealii::Triangulation<dim> &triangulation,
           const unsigned int          refinements) const override;

  private:
    const std::string arguments;
    const Constants   constants;
  };
} // namespace hrcontact

#endif
