#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi.templates.h>

#include <hrcontact/core/boundary_id_check.h>

#include <utility>
#include <vector>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::set<types::boundary_id>
  mesh_boundary_ids(const Triangulation<dim> &triangulation,
                    const MPI_Comm            communicator)
  {
    std::set<types::boundary_id> ids;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            ids.insert(cell->face(f)->boundary_id());
    if (Utilities::MPI::job_supports_mpi() &&
        Utilities::MPI::n_mpi_processes(communicator) > 1)
      {
        const std::vector<types::boundary_id> all =
          Utilities::MPI::compute_set_union(
            std::vector<types::boundary_id>(ids.begin(), ids.end()),
            communicator);
        ids.insert(all.begin(), all.end());
      }
    return ids;
  }

  template <int dim>
  void
  check_named_boundary_ids(const Scene<dim>         &scene,
                           const Triangulation<dim> &triangulation,
                           const MPI_Comm            communicator)
  {
    std::vector<std::pair<std::string, types::boundary_id>> named;
    for (const auto &traction : scene.tractions)
      named.emplace_back("Loads/Tractions", traction.first);
    for (const auto &pressure : scene.projected_pressures)
      named.emplace_back("Loads/Projected pressures", pressure.first);
    for (const auto &source : scene.constraints)
      for (const types::boundary_id id : source->boundary_ids())
        named.emplace_back(source->entry(), id);
    const std::set<types::boundary_id> on_mesh =
      mesh_boundary_ids(triangulation, communicator);
    for (const auto &[entry, id] : named)
      if (on_mesh.count(id) == 0)
        {
          const auto  names = scene.grid->boundary_names();
          std::string listed;
          for (const types::boundary_id m : on_mesh)
            {
              listed += (listed.empty() ? "" : ", ") + std::to_string(m);
              const auto name = names.find(m);
              if (name != names.end())
                listed += " (" + name->second + ")";
            }
          throw InputError(entry + ": boundary id " + std::to_string(id) +
                           " is not on the mesh (Geometry/Grid generator = " +
                           scene.grid_generator +
                           "); the mesh's boundary ids are " + listed + ".");
        }
  }

  template std::set<types::boundary_id>
  mesh_boundary_ids(const Triangulation<2> &, const MPI_Comm);
  template std::set<types::boundary_id>
  mesh_boundary_ids(const Triangulation<3> &, const MPI_Comm);
  template void
  check_named_boundary_ids(const Scene<2> &,
                           const Triangulation<2> &,
                           const MPI_Comm);
  template void
  check_named_boundary_ids(const Scene<3> &,
                           const Triangulation<3> &,
                           const MPI_Comm);
} // namespace hrcontact
