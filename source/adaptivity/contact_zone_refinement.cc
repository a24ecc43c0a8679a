#include <deal.II/base/bounding_box.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/rtree.h>

#include <hrcontact/adaptivity/contact_zone_refinement.h>
#include <hrcontact/core/input.h>
#include <hrcontact/postprocess/contact_fields.h>

#include <algorithm>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  ContactZoneRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    prm.declare_entry(
      "Contact zone depth",
      "0.5",
      Patterns::Double(0),
      "After each adaptive cycle's marks, the cells within this many times "
      "the pressed contact zone's size of a pressed face are refined up to "
      "one level below the finest pressed face (0: off; no effect without "
      "contact). The estimators refine the zone's edge and leave its middle "
      "and the body beneath coarse, where the peak pressure is set: Hertz, "
      "kelly, 4 cycles: peak -0.04 % instead of -0.12 % at 20,898 dofs "
      "instead of 20,714 (doc/adaptivity.md).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ContactZoneRefinement<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    depth = prm.get_double("Contact zone depth");
    prm.leave_subsection();
  }

  template <int dim>
  unsigned int
  ContactZoneRefinement<dim>::add_to(const Results<dim> &results,
                                     RefinementStep     &step) const
  {
    if (depth == 0 || !results.contact)
      return 0;
    const MPI_Comm           communicator = results.partition.communicator;
    const ContactFields<dim> fields(results);
    const auto              &dof_handler = fields.get_dof_handler();
    Vector<double>           status(dof_handler.get_fe().n_dofs_per_cell());
    // The pressed faces' centres, and the finest level among their cells
    // once this step's marks are done.
    std::vector<Point<dim>> centres;
    int                     finest = -1;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(fields.get_status(), status);
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->at_boundary(f))
                continue;
              bool all = true, pressed = false;
              for (const unsigned int v : cell->face(f)->vertex_indices())
                {
                  const double s =
                    status[GeometryInfo<dim>::face_to_cell_vertices(f, v)];
                  all &= s >= 1;
                  pressed |= s == 2;
                }
              if (!(all && pressed))
                continue;
              centres.push_back(cell->face(f)->center());
              finest =
                std::max(finest,
                         cell->level() +
                           int(step.refine.count(cell->id().to_string()) > 0));
            }
        }
    finest = Utilities::MPI::max(finest, communicator);
    std::vector<Point<dim>> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, centres))
      all.insert(all.end(), part.begin(), part.end());
    if (all.empty())
      return 0;
    const BoundingBox<dim> box(all);
    const double reach = depth * box.get_boundary_points().first.distance(
                                   box.get_boundary_points().second);
    const int  target = finest - 1;
    const auto tree   = pack_rtree(all);

    std::vector<std::string> refine, keep;
    for (const auto &cell : results.triangulation().active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->level() > target)
          continue;
        const Point<dim> c    = cell->center();
        bool             near = false;
        for (const auto &p : tree | boost::geometry::index::adaptors::queried(
                                      boost::geometry::index::nearest(c, 1)))
          near = p.distance(c) <= reach;
        if (!near)
          continue;
        const std::string id = cell->id().to_string();
        if (cell->level() < target && step.refine.count(id) == 0)
          refine.push_back(id);
        // Neither the block nor the cells just at its level coarsen.
        if (step.coarsen.count(id) > 0)
          keep.push_back(id);
      }
    // The step is replayed on other partitions: every process keeps the
    // same sets.
    for (const auto &part : Utilities::MPI::all_gather(communicator, keep))
      for (const auto &id : part)
        step.coarsen.erase(id);
    unsigned int added = 0;
    for (const auto &part : Utilities::MPI::all_gather(communicator, refine))
      {
        step.refine.insert(part.begin(), part.end());
        added += part.size();
      }
    return added;
  }

  template class ContactZoneRefinement<2>;
  template class ContactZoneRefinement<3>;
} // namespace hrcontact
