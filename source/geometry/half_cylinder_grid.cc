#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <hrcontact/geometry/half_cylinder_grid.h>

#include <cmath>
#include <stdexcept>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    struct HalfCylinderArguments
    {
      double R = 1, phi_c = 0.1, q = 1;
    };

    HalfCylinderArguments
    read_arguments(const std::string &arguments)
    {
      const auto parts = split_and_trim(arguments, ':');
      if (parts.size() != 3)
        throw InputError(
          "Geometry: half_cylinder takes 'R : phi_c : q' (radius, angle in "
          "radians of the finely meshed arc, radial grading exponent).");
      HalfCylinderArguments a;
      try
        {
          a.R     = std::stod(parts[0]);
          a.phi_c = std::stod(parts[1]);
          a.q     = std::stod(parts[2]);
        }
      catch (const std::invalid_argument &)
        {
          throw InputError("Geometry: cannot read the half_cylinder "
                           "arguments '" +
                           arguments + "' as 'R : phi_c : q'.");
        }
      if (!(a.R > 0) || !(a.phi_c > 0) || !(a.phi_c <= numbers::PI / 4) ||
          !(a.q >= 1))
        throw InputError("Geometry: half_cylinder needs R > 0, 0 < phi_c <= "
                         "pi/4 and q >= 1.");
      return a;
    }

    /** The quarter disk x >= 0, y <= 0 of three cells, its arc on a
     * spherical manifold, with the boundary ids. */
    void
    coarse_half_cylinder(Triangulation<2> &tria, const HalfCylinderArguments &a)
    {
      GridGenerator::quarter_hyper_ball(tria, Point<2>(), a.R);
      GridTools::transform(
        [](const Point<2> &x) { return Point<2>(x[1], -x[0]); }, tria);
      const double tol = 1e-10 * a.R;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2> c = cell->face(f)->center();
              cell->face(f)->set_boundary_id(std::abs(c[0]) < tol ? 0 :
                                             std::abs(c[1]) < tol ? 1 :
                                                                    2);
            }
    }

    /** The grading: a polar map that keeps the circle. */
    Point<2>
    graded(const Point<2> &x, const HalfCylinderArguments &a)
    {
      const double r = x.norm();
      if (r == 0)
        return x;
      const double phi     = std::atan2(x[0], -x[1]); // from -y towards +x
      const double half_pi = numbers::PI / 2;
      const double t       = std::min(1., std::max(0., phi / half_pi));
      // phi(t) = 2 phi_c t on [0, 1/2]; then the same slope plus a
      // quadratic term reaching pi/2 at t = 1.
      const double c       = (half_pi - 2 * a.phi_c) / 0.25;
      const double phi_new = (t <= 0.5) ? 2 * a.phi_c * t :
                                          a.phi_c + 2 * a.phi_c * (t - 0.5) +
                                            c * (t - 0.5) * (t - 0.5);
      const double r_new = a.R * (1 - std::pow(std::max(0., 1 - r / a.R), a.q));
      return Point<2>(r_new * std::sin(phi_new), -r_new * std::cos(phi_new));
    }

    void
    half_cylinder(Triangulation<2>  &tria,
                  const std::string &arguments,
                  const unsigned int refinements)
    {
      const HalfCylinderArguments a = read_arguments(arguments);
      coarse_half_cylinder(tria, a);
      tria.refine_global(refinements);
      GridTools::transform([&a](const Point<2> &x) { return graded(x, a); },
                           tria);
      tria.reset_all_manifolds();
      tria.set_all_manifold_ids(numbers::flat_manifold_id);
    }

    template <int dim>
    void
    half_cylinder(Triangulation<dim> &, const std::string &, const unsigned int)
    {
      throw InputError("Geometry: half_cylinder is a 2D grid.");
    }
  } // namespace

  template <int dim>
  HalfCylinderGrid<dim>::HalfCylinderGrid(const std::string &arguments,
                                          const Constants &)
    : arguments(arguments)
  {}

  template <int dim>
  void
  HalfCylinderGrid<dim>::create(Triangulation<dim> &triangulation,
                                const unsigned int  refinements) const
  {
    half_cylinder(triangulation, arguments, refinements);
  }

  template <int dim>
  bool
  HalfCylinderGrid<dim>::create_coarse(Triangulation<dim> &triangulation) const
  {
    if constexpr (dim == 2)
      coarse_half_cylinder(triangulation, read_arguments(arguments));
    else
      half_cylinder(triangulation, arguments, 0);
    return true;
  }

  template <int dim>
  typename MeshGenerator<dim>::VertexMap
  HalfCylinderGrid<dim>::refined_vertex_map() const
  {
    if constexpr (dim == 2)
      return [a = read_arguments(arguments)](const Point<dim> &x,
                                             const types::material_id) {
        return graded(x, a);
      };
    else
      return MeshGenerator<dim>::refined_vertex_map();
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  HalfCylinderGrid<dim>::boundary_names() const
  {
    return {{0, "symmetry plane x = 0"},
            {1, "loaded diameter y = 0"},
            {2, "curved surface"}};
  }

  template class HalfCylinderGrid<2>;
  template class HalfCylinderGrid<3>;

  HRCONTACT_REGISTER_MESH_GENERATOR(HalfCylinderGrid, "half_cylinder")
} // namespace hrcontact
