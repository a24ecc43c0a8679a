#include <deal.II/dofs/dof_tools.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>

#include <algorithm>

namespace hrcontact
{
  using namespace dealii;

  void
  DofPartition::add_dofs_of_rows_across_nodes(const EquilibriumSystem &system)
  {
    if (!distributed())
      return;
    std::vector<types::global_dof_index> coupled;
    for (const auto &row : system.rows)
      if (system.dof_node(row.combination.front().first) !=
          system.dof_node(row.combination.back().first))
        for (const auto &[dof, c] : row.combination)
          coupled.push_back(dof);
    std::sort(coupled.begin(), coupled.end());
    coupled.erase(std::unique(coupled.begin(), coupled.end()), coupled.end());
    relevant.add_indices(coupled.begin(), coupled.end());
    relevant.compress();
  }

  std::string
  DofPartition::describe() const
  {
    const auto n_owned = Utilities::MPI::all_gather(
      communicator, static_cast<unsigned long>(owned.n_elements()));
    return std::to_string(n_processes) + " MPI processes (p4est partition), " +
           std::to_string(*std::min_element(n_owned.begin(), n_owned.end())) +
           " to " +
           std::to_string(*std::max_element(n_owned.begin(), n_owned.end())) +
           " displacement dofs each";
  }

  bool
  is_root_process(const MPI_Comm communicator)
  {
    return !Utilities::MPI::job_supports_mpi() ||
           Utilities::MPI::this_mpi_process(communicator) == 0;
  }

  DofPartition
  serial_partition(const unsigned int n_dofs, const unsigned int n_cells)
  {
    DofPartition partition;
    partition.owned    = complete_index_set(n_dofs);
    partition.relevant = complete_index_set(n_dofs);
    partition.owned_cell.assign(n_cells, true);
    return partition;
  }

  namespace
  {
    /** A parallel::distributed::Triangulation's own ownership, cell by cell
     * (indices of this process's active cells, artificial ones included
     * and not owned). */
    template <int dim>
    DofPartition
    partition_of_distributed_mesh(const Triangulation<dim> &triangulation,
                                  const DoFHandler<dim>    &dof_handler,
                                  const MPI_Comm            communicator,
                                  const unsigned int        n_processes)
    {
      DofPartition partition;
      partition.communicator = communicator;
      partition.n_processes  = n_processes;
      partition.process      = Utilities::MPI::this_mpi_process(communicator);
      partition.distributed_mesh = true;
      partition.owned            = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, partition.relevant);
      partition.owned_cell.assign(triangulation.n_active_cells(), false);
      for (const auto &cell : triangulation.active_cell_iterators())
        partition.owned_cell[cell->active_cell_index()] =
          cell->is_locally_owned();
      return partition;
    }

    /** The cell of the serial mesh a forest cell is: the coarse cell by its
     * deal.II index (p4est numbers its trees differently), then the child
     * path. */
    template <int dim>
    typename DoFHandler<dim>::active_cell_iterator
    same_cell_of_serial_mesh(
      const typename DoFHandler<dim>::active_cell_iterator &forest_cell,
      const Triangulation<dim>                             &triangulation,
      const DoFHandler<dim>                                &dof_handler)
    {
      std::vector<unsigned int>                  path;
      typename Triangulation<dim>::cell_iterator ancestor = forest_cell;
      while (ancestor->level() > 0)
        {
          const auto parent = ancestor->parent();
          path.push_back(parent->child_iterator_to_index(ancestor));
          ancestor = parent;
        }
      typename Triangulation<dim>::cell_iterator serial(&triangulation,
                                                        0,
                                                        ancestor->index());
      for (auto child = path.rbegin(); child != path.rend(); ++child)
        serial = serial->child(*child);
      AssertThrow(serial->is_active(), ExcInternalError());
      return typename DoFHandler<dim>::active_cell_iterator(&triangulation,
                                                            serial->level(),
                                                            serial->index(),
                                                            &dof_handler);
    }
  } // namespace

  template <int dim>
  DofPartition
  partition_with_p4est(const Triangulation<dim> &triangulation,
                       const DoFHandler<dim>    &dof_handler,
                       const MPI_Comm            communicator)
  {
    // Programs that never initialise MPI (small test programs) run serially.
    const unsigned int n_processes =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(communicator) :
        1;
    if (n_processes == 1)
      return serial_partition(dof_handler.n_dofs(),
                              triangulation.n_active_cells());

    // A distributed mesh: its own ownership.
    if (dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
          &triangulation))
      return partition_of_distributed_mesh(triangulation,
                                           dof_handler,
                                           communicator,
                                           n_processes);

    const unsigned int finest = triangulation.n_levels() - 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->level() != static_cast<int>(finest))
        throw InputError("Parallel runs: the p4est partition needs a "
                         "uniformly refined mesh (Mesh/Global refinements).");

    // The forest: the coarse cells in the same order, without manifolds
    // (only the topology matters for the partition), refined alike.
    auto  description = GridTools::get_coarse_mesh_description(triangulation);
    auto &vertices    = std::get<0>(description);
    auto &cells       = std::get<1>(description);
    auto &subcells    = std::get<2>(description);
    for (auto &c : cells)
      c.manifold_id = numbers::flat_manifold_id;
    for (auto &l : subcells.boundary_lines)
      l.manifold_id = numbers::flat_manifold_id;
    for (auto &q : subcells.boundary_quads)
      q.manifold_id = numbers::flat_manifold_id;
    parallel::distributed::Triangulation<dim> forest(communicator);
    forest.create_triangulation(vertices, cells, subcells);
    forest.refine_global(finest);
    DoFHandler<dim> forest_dofs(forest);
    forest_dofs.distribute_dofs(dof_handler.get_fe());

    DofPartition partition;
    partition.communicator = communicator;
    partition.n_processes  = n_processes;
    partition.process      = Utilities::MPI::this_mpi_process(communicator);
    partition.owned.set_size(dof_handler.n_dofs());
    partition.relevant.set_size(dof_handler.n_dofs());
    partition.owned_cell.assign(triangulation.n_active_cells(), false);

    const IndexSet    &forest_owned = forest_dofs.locally_owned_dofs();
    const unsigned int n            = dof_handler.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> forest_cell_dofs(n), cell_dofs(n);
    std::vector<types::global_dof_index> owned, relevant;
    for (const auto &forest_cell : forest_dofs.active_cell_iterators())
      {
        if (forest_cell->is_artificial())
          continue;
        const auto cell =
          same_cell_of_serial_mesh(forest_cell, triangulation, dof_handler);
        forest_cell->get_dof_indices(forest_cell_dofs);
        cell->get_dof_indices(cell_dofs);
        for (unsigned int i = 0; i < n; ++i)
          {
            relevant.push_back(cell_dofs[i]);
            if (forest_owned.is_element(forest_cell_dofs[i]))
              owned.push_back(cell_dofs[i]);
          }
        if (forest_cell->is_locally_owned())
          partition.owned_cell[cell->active_cell_index()] = true;
      }
    std::sort(owned.begin(), owned.end());
    owned.erase(std::unique(owned.begin(), owned.end()), owned.end());
    std::sort(relevant.begin(), relevant.end());
    relevant.erase(std::unique(relevant.begin(), relevant.end()),
                   relevant.end());
    partition.owned.add_indices(owned.begin(), owned.end());
    partition.relevant.add_indices(relevant.begin(), relevant.end());
    partition.owned.compress();
    partition.relevant.compress();

    // Every dof and cell has exactly one owner.
    const auto n_owned = Utilities::MPI::sum(
      static_cast<unsigned long>(partition.owned.n_elements()), communicator);
    const auto n_cells =
      Utilities::MPI::sum(static_cast<unsigned long>(
                            std::count(partition.owned_cell.begin(),
                                       partition.owned_cell.end(),
                                       true)),
                          communicator);
    AssertThrow(n_owned == dof_handler.n_dofs() &&
                  forest_owned.n_elements() == partition.owned.n_elements() &&
                  n_cells == triangulation.n_active_cells(),
                ExcMessage("the p4est partition does not map onto the serial "
                           "mesh one to one"));
    return partition;
  }

  template DofPartition
  partition_with_p4est<2>(const Triangulation<2> &,
                          const DoFHandler<2> &,
                          const MPI_Comm);
  template DofPartition
  partition_with_p4est<3>(const Triangulation<3> &,
                          const DoFHandler<3> &,
                          const MPI_Comm);
} // namespace hrcontact
