#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <hrcontact/geometry/cooks_membrane_grid.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  CooksMembraneGrid<dim>::CooksMembraneGrid(const std::string &arguments,
                                            const Constants   &constants)
  {
    if (dim != 2)
      throw InputError("Geometry: cooks_membrane is a 2D grid.");
    if (Utilities::trim(arguments).empty())
      return;
    const double n = evaluate_constant_expression(arguments,
                                                  constants,
                                                  "Geometry/Grid arguments");
    if (!(n >= 1 && n == std::floor(n) && n < 1e6))
      throw InputError("Geometry: cooks_membrane takes the number of cells "
                       "per side, a whole number of at least 1.");
    cells_per_side = static_cast<unsigned int>(n);
  }

  template <int dim>
  void
  CooksMembraneGrid<dim>::create(Triangulation<dim> &triangulation,
                                 const unsigned int  refinements) const
  {
    if constexpr (dim == 2)
      {
        GridGenerator::subdivided_hyper_rectangle(
          triangulation,
          std::vector<unsigned int>(2, cells_per_side),
          Point<2>(0, 0),
          Point<2>(1, 1),
          true);
        // (s, t) -> x = 48 s, y = 44 s + 44 t - 28 s t: the corners (0, 0),
        // (48, 44), (0, 44), (48, 60). A refined cell's new vertices are the
        // map's own (midpoints and centres of a bilinear map).
        GridTools::transform(
          [](const Point<2> &p) {
            return Point<2>(48 * p[0],
                            44 * p[0] + 44 * p[1] - 28 * p[0] * p[1]);
          },
          triangulation);
        triangulation.refine_global(refinements);
      }
    else
      (void)triangulation, (void)refinements;
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  CooksMembraneGrid<dim>::boundary_names() const
  {
    return {{0, "clamped edge x = 0"},
            {1, "loaded edge x = 48"},
            {2, "lower edge"},
            {3, "upper edge"}};
  }

  template class CooksMembraneGrid<2>;
  template class CooksMembraneGrid<3>;

  HRCONTACT_REGISTER_MESH_GENERATOR(CooksMembraneGrid, "cooks_membrane")
} // namespace hrcontact
