#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/discretisation/hanging_nodes.h>

#include <map>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  find_hanging_nodes(const DoFHandler<dim> &dof_handler,
                     const IndexSet        &relevant,
                     EquilibriumSystem     &system)
  {
    system.hanging_nodes.clear();
    system.hanging_nodes.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, system.hanging_nodes);
    system.hanging_nodes.close();
    // Each hanging dof counted once, by the process that owns it.
    unsigned int n_owned = 0;
    for (const auto &line : system.hanging_nodes.get_lines())
      n_owned += dof_handler.locally_owned_dofs().is_element(line.index);
    const auto *parallel_mesh =
      dynamic_cast<const parallel::TriangulationBase<dim> *>(
        &dof_handler.get_triangulation());
    system.n_hanging_dofs =
      parallel_mesh ?
        Utilities::MPI::sum(n_owned, parallel_mesh->get_communicator()) :
        n_owned;
    if (system.n_hanging_dofs == 0)
      system.hanging_nodes.clear();
  }

  void
  add_hanging_shares(EquilibriumSystem &system)
  {
    if (system.n_hanging_dofs == 0)
      return;
    // The hanging dofs that depend on each parent dof, with a_hj.
    std::map<types::global_dof_index,
             std::vector<std::pair<types::global_dof_index, double>>>
      children;
    for (const auto &line : system.hanging_nodes.get_lines())
      for (const auto &[parent, a] : line.entries)
        children[parent].emplace_back(line.index, a);
    for (EquilibriumRow &row : system.rows)
      {
        std::map<types::global_dof_index, double> shares;
        for (const auto &[dof, c] : row.combination)
          {
            const auto found = children.find(dof);
            if (found != children.end())
              for (const auto &[h, a] : found->second)
                shares[h] += c * a;
          }
        row.shares.assign(shares.begin(), shares.end());
      }
  }

  template void
  find_hanging_nodes<2>(const DoFHandler<2> &,
                        const IndexSet &,
                        EquilibriumSystem &);
  template void
  find_hanging_nodes<3>(const DoFHandler<3> &,
                        const IndexSet &,
                        EquilibriumSystem &);
} // namespace hrcontact
