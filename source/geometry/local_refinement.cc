#include <deal.II/base/utilities.h>

#include <hrcontact/core/input.h>
#include <hrcontact/geometry/local_refinement.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  LocalRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry(
        "Refinement region",
        "",
        Patterns::Anything(),
        "A box 'x0, y0 [, z0] : x1, y1 [, z1]' (expressions of the "
        "constants): the cells whose centres lie in it are refined again "
        "after Geometry/Global refinements, Region refinements times. Empty: "
        "none. The mesh then has hanging nodes, which the condensed path "
        "imposes (one process for now).");
      prm.declare_entry("Region refinements",
                        "0",
                        Patterns::Integer(0, 8),
                        "How many times the cells in the Refinement region "
                        "are refined (each time the cells whose centres lie "
                        "in the box).");
    }
    prm.leave_subsection();
  }

  template <int dim>
  void
  LocalRefinement<dim>::parse_parameters(
    ParameterHandler                    &prm,
    const std::map<std::string, double> &constants)
  {
    prm.enter_subsection("Mesh refinement");
    const std::string region = Utilities::trim(prm.get("Refinement region"));
    n_refinements            = prm.get_integer("Region refinements");
    prm.leave_subsection();
    if (region.empty())
      {
        if (n_refinements > 0)
          throw InputError("Mesh refinement/Region refinements = " +
                           std::to_string(n_refinements) +
                           " needs a Refinement region (a box 'x0, y0 : "
                           "x1, y1').");
        return;
      }
    const auto        corners = split_and_trim(region, ':');
    const std::string where   = "Mesh refinement/Refinement region";
    if (corners.size() != 2)
      throw InputError(where + " = '" + region +
                       "': expected two corners 'x0, y0" +
                       (dim == 3 ? ", z0" : "") + " : x1, y1" +
                       (dim == 3 ? ", z1" : "") + "'.");
    for (unsigned int k = 0; k < 2; ++k)
      {
        const auto coordinates = split_and_trim(corners[k], ',');
        if (coordinates.size() != dim)
          throw InputError(where + " = '" + region + "': the corner '" +
                           corners[k] + "' needs " + std::to_string(dim) +
                           " coordinates.");
        for (unsigned int d = 0; d < dim; ++d)
          (k == 0 ? lower : upper)[d] =
            evaluate_constant_expression(coordinates[d], constants, where);
      }
    for (unsigned int d = 0; d < dim; ++d)
      if (!(lower[d] < upper[d]))
        throw InputError(where + " = '" + region +
                         "': the first corner must lie below the second in "
                         "every coordinate.");
  }

  template <int dim>
  bool
  LocalRefinement<dim>::active() const
  {
    return n_refinements > 0;
  }

  template <int dim>
  void
  LocalRefinement<dim>::apply(
    Triangulation<dim>                           &triangulation,
    const typename MeshGenerator<dim>::VertexMap &place) const
  {
    for (unsigned int k = 0; k < n_refinements; ++k)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const Point<dim> c = place(cell->center(), cell->material_id());
              bool             inside = true;
              for (unsigned int d = 0; d < dim; ++d)
                inside = inside && lower[d] <= c[d] && c[d] <= upper[d];
              if (inside)
                cell->set_refine_flag();
            }
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template <int dim>
  void
  LocalRefinement<dim>::centre_hanging_vertices(
    Triangulation<dim> &triangulation)
  {
    // A face of an active cell with children: the finer neighbour's
    // vertices on it hang. Edges first, then (3D) the face's centre.
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->has_children())
          {
            if constexpr (dim == 2)
              face->child(0)->vertex(1) =
                0.5 * (face->vertex(0) + face->vertex(1));
            else
              {
                for (unsigned int l = 0; l < face->n_lines(); ++l)
                  {
                    const auto line = face->line(l);
                    if (line->has_children())
                      line->child(0)->vertex(1) =
                        0.5 * (line->vertex(0) + line->vertex(1));
                  }
                Point<dim> centre;
                for (unsigned int v = 0; v < face->n_vertices(); ++v)
                  centre += face->vertex(v) / double(face->n_vertices());
                face->child(0)->vertex(3) = centre;
              }
          }
  }

  template class LocalRefinement<2>;
  template class LocalRefinement<3>;
} // namespace hrcontact
