#ifndef hrcontact_cooks_membrane_grid_h
#define hrcontact_cooks_membrane_grid_h

#include <hrcontact/geometry/mesh_generator.h>

namespace hrcontact
{
  /**
   * Grid "cooks_membrane" (2D): Cook's tapered panel, the quadrilateral
   * (0, 0), (48, 44), (48, 60), (0, 44), meshed n x n by the bilinear map of
   * the unit square (the benchmark's meshes: every refinement halves the
   * cells along both sides). Argument 'n', cells per side (default 1).
   * Boundary ids: 0 the clamped edge x = 0, 1 the loaded edge x = 48, 2 the
   * lower edge, 3 the upper edge.
   */
  template <int dim>
  class CooksMembraneGrid : public MeshGenerator<dim>
  {
  public:
    CooksMembraneGrid(const std::string &arguments, const Constants &constants);
    std::map<dealii::types::boundary_id, std::string>
    boundary_names() const override;
    void
    create(dealii::Triangulation<dim> &triangulation,
           const unsigned int          refinements) const override;

  private:
    unsigned int cells_per_side = 1;
  };
} // namespace hrcontact

#endif
