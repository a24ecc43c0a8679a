#include <hrcontact/geometry/tunnel_lining_grid.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  TunnelLiningGrid<dim>::TunnelLiningGrid(const std::string &arguments,
                                          const Constants   &constants)
  {
    if (dim != 2)
      throw InputError("Geometry: tunnel_lining is a 2D grid.");
    geometry = std::make_shared<const TunnelLining>(arguments, constants);
  }

  template <int dim>
  void
  TunnelLiningGrid<dim>::create(Triangulation<dim> &triangulation,
                                const unsigned int  refinements) const
  {
    if constexpr (dim == 2)
      {
        geometry->create_coarse_mesh(triangulation);
        triangulation.refine_global(refinements);
      }
    else
      (void)triangulation, (void)refinements;
  }

  template <int dim>
  std::string
  TunnelLiningGrid<dim>::fixed_geometry_reason() const
  {
    return "tunnel_lining cannot be rotated or distorted (its sections are "
           "computed from the arcs)";
  }

  template <int dim>
  std::shared_ptr<const TunnelLining>
  TunnelLiningGrid<dim>::lining() const
  {
    return geometry;
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  TunnelLiningGrid<dim>::boundary_names() const
  {
    return {{0, "intrados"},
            {1, "extrados"},
            {2, "symmetry cut at the crown top"},
            {3, "symmetry cut at the invert bottom"}};
  }

  template class TunnelLiningGrid<2>;
  template class TunnelLiningGrid<3>;

  HRCONTACT_REGISTER_MESH_GENERATOR(TunnelLiningGrid, "tunnel_lining")
} // namespace hrcontact
