#ifndef hrcontact_tunnel_lining_grid_h
#define hrcontact_tunnel_lining_grid_h

#include <hrcontact/geometry/mesh_generator.h>
#include <hrcontact/geometry/tunnel_lining.h>

#include <memory>

namespace hrcontact
{
  /**
   * Grid "tunnel_lining" (2D): the right half of a lining of two circular
   * arcs (TunnelLining, doc/tunnel.md), whose geometry the lining
   * postprocessor needs for its sections; it may not be distorted or
   * rotated.
   */
  template <int dim>
  class TunnelLiningGrid : public MeshGenerator<dim>
  {
  public:
    TunnelLiningGrid(const std::string &arguments, const Constants &constants);
    void
    create(dealii::Triangulation<dim> &triangulation,
           const unsigned int          refinements) const override;
    std::string
    fixed_geometry_reason() const override;
    std::map<dealii::types::boundary_id, std::string>
    boundary_names() const override;

    /** The lining's geometry. */
    std::shared_ptr<const TunnelLining>
    lining() const;

  private:
    std::shared_ptr<const TunnelLining> geometry;
  };
} // namespace hrcontact

#endif
