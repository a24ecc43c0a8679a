#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/discretisation/hanging_nodes.h>

#include <map>
#include <set>

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

  HangingChildren::HangingChildren(const EquilibriumSystem &system)
  {
    for (const auto &line : system.hanging_nodes.get_lines())
      for (const auto &[parent, a] : line.entries)
        children[parent].emplace_back(line.index, a);
  }

  std::vector<std::pair<types::global_dof_index, double>>
  HangingChildren::shares_of(
    const std::vector<std::pair<types::global_dof_index, double>> &combination)
    const
  {
    std::map<types::global_dof_index, double> shares;
    for (const auto &[dof, c] : combination)
      if (const auto found = children.find(dof); found != children.end())
        for (const auto &[h, a] : found->second)
          shares[h] += c * a;
    return {shares.begin(), shares.end()};
  }

  void
  add_hanging_shares(EquilibriumSystem &system)
  {
    if (system.n_hanging_dofs == 0)
      return;
    const HangingChildren children(system);
    for (EquilibriumRow &row : system.rows)
      row.shares = children.shares_of(row.combination);
  }

  HangingShareForces::HangingShareForces(const EquilibriumSystem &system,
                                         const DofPartition      &partition)
    : any(system.n_hanging_dofs > 0)
  {
    if (!any)
      return;
    std::set<types::global_dof_index> shared;
    for (const auto &row : system.rows)
      for (const auto &[h, w] : row.shares)
        shared.insert(h);
    for (unsigned int c = 0; c < system.n_cells(); ++c)
      if (partition.owned_cell[c] && system.is_stored(c))
        for (const auto h : system.cell_displacement_dofs[c])
          if (shared.count(h) > 0)
            for (const auto j : system.cell_stress_dofs[c])
              {
                const double b = system.B.el(system.b_row(h), j);
                if (b != 0)
                  terms_.push_back({h, j, b});
              }
    forces.reinit(partition.owned, partition.relevant, partition.communicator);
  }

  void
  HangingShareForces::evaluate(const std::function<double(std::size_t)> &stress)
  {
    if (!any)
      return;
    forces = 0;
    for (std::size_t k = 0; k < terms_.size(); ++k)
      forces(terms_[k].hanging) += terms_[k].b * stress(k);
    forces.compress(VectorOperation::add);
    forces.update_ghost_values();
  }

  double
  HangingShareForces::of_row(const EquilibriumRow &row) const
  {
    double sum = 0;
    for (const auto &[h, w] : row.shares)
      sum += w * forces(h);
    return sum;
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
