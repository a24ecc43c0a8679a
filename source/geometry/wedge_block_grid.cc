#include <deal.II/base/numbers.h>

#include <deal.II/grid/grid_generator.h>

#include <hrcontact/geometry/wedge_block_grid.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  WedgeBlockGrid<dim>::WedgeBlockGrid(const std::string &arguments,
                                      const Constants   &constants)
    : arguments(arguments)
    , constants(constants)
  {}

  template <int dim>
  void
  WedgeBlockGrid<dim>::create(Triangulation<dim> &triangulation,
                              const unsigned int  refinements) const
  {
    // deal.II's subdivided_parallelepiped (not reachable by name):
    // edges a = (L_a, 0) and b = L_b (cos theta, sin theta) from the
    // origin, n_a x n_b cells, colorized: 0 the face along b, 1 its
    // opposite, 2 the face along a, 3 its opposite.
    const auto parts = split_and_trim(arguments, ':');
    if (dim != 2 || parts.size() != 5)
      throw InputError("Geometry: wedge_block is 2D and takes 'L_a : L_b "
                       ": theta (degrees) : n_a : n_b'.");
    double v[5];
    for (unsigned int k = 0; k < 5; ++k)
      v[k] = evaluate_constant_expression(parts[k],
                                          constants,
                                          "Geometry/Grid arguments");
    if (!(v[0] > 0 && v[1] > 0 && v[2] > 0 && v[2] < 180 && v[3] >= 1 &&
          v[4] >= 1))
      throw InputError("Geometry: wedge_block needs L_a, L_b > 0, 0 < "
                       "theta < 180 and at least one cell per edge.");
    if constexpr (dim == 2)
      {
        const double theta = v[2] * numbers::PI / 180.;
        Point<dim>   corners[dim];
        corners[0][0]                  = v[0];
        corners[1][0]                  = v[1] * std::cos(theta);
        corners[1][1]                  = v[1] * std::sin(theta);
        unsigned int subdivisions[dim] = {static_cast<unsigned int>(v[3]),
                                          static_cast<unsigned int>(v[4])};
        GridGenerator::subdivided_parallelepiped<dim>(triangulation,
                                                      subdivisions,
                                                      corners,
                                                      true);
        triangulation.refine_global(refinements);
      }
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  WedgeBlockGrid<dim>::boundary_names() const
  {
    return {{0, "face along b"},
            {1, "face opposite the face along b"},
            {2, "face along a"},
            {3, "face opposite the face along a"}};
  }

  template class WedgeBlockGrid<2>;
  template class WedgeBlockGrid<3>;

  HRCONTACT_REGISTER_MESH_GENERATOR(WedgeBlockGrid, "wedge_block")
} // namespace hrcontact
