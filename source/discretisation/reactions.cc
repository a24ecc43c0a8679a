#include <deal.II/base/mpi.h>

#include <hrcontact/discretisation/hanging_nodes.h>
#include <hrcontact/discretisation/reactions.h>

#include <map>
#include <memory>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** Under MPI: the index among the Q rows of each pair row, by its
     * slave node (rows over the nodes of two bodies). Empty serially. */
    std::map<unsigned int, unsigned int>
    pair_rows_by_slave_node(const EquilibriumSystem &system,
                            const DofPartition      &partition)
    {
      std::map<unsigned int, unsigned int> pair_row_at;
      if (partition.distributed())
        for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
          {
            const EquilibriumRow &row = system.rows[system.contact_rows[k]];
            if (system.dof_node(row.combination.front().first) !=
                system.dof_node(row.combination.back().first))
              pair_row_at[row.node] = k;
          }
      return pair_row_at;
    }
  } // namespace

  void
  row_reactions(const EquilibriumSystem         &system,
                const DofPartition              &partition,
                const FieldVector               &unknowns,
                const std::vector<unsigned int> &rows,
                const std::vector<double>       &pair_reactions,
                std::vector<double>             &values)
  {
    const std::map<unsigned int, unsigned int> pair_row_at =
      pair_rows_by_slave_node(system, partition);
    values.assign(rows.size(), 0.);
    // A locally refined mesh: the hanging nodes' forces the rows share.
    std::unique_ptr<HangingShareForces> shares;
    if (system.n_hanging_dofs > 0)
      {
        shares = std::make_unique<HangingShareForces>(system, partition);
        shares->evaluate([&](const std::size_t t) {
          return unknowns(shares->terms()[t].column);
        });
      }
    // With pair rows: the shares of a row's own node alone (its shares
    // also hold alpha times the slave's, which the slave's reaction
    // carries).
    std::unique_ptr<HangingChildren> children;
    if (shares && !pair_row_at.empty())
      children = std::make_unique<HangingChildren>(system);
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        const EquilibriumRow &row = system.rows[rows[k]];
        if (!partition.owned.is_element(row.combination.front().first))
          continue;
        if (pair_row_at.empty())
          {
            values[k] = system.row_times(row, unknowns);
            if (shares)
              values[k] += shares->of_row(row);
            values[k] -= system.row_load(row);
            continue;
          }
        EquilibriumRow own = row;
        own.combination.clear();
        own.direction.clear();
        std::map<unsigned int, double> alpha;
        for (unsigned int e = 0; e < row.combination.size(); ++e)
          {
            const auto [dof, c] = row.combination[e];
            if (c == 0) // a pair row's master entries
              continue;
            if (system.dof_node(dof) == row.node)
              own.combination.emplace_back(dof, c);
            else
              {
                const unsigned int    slave = system.dof_node(dof);
                const EquilibriumRow &q =
                  system.rows[system.contact_rows[pair_row_at.at(slave)]];
                // c = alpha n over the slave's dofs; n = d_q there.
                alpha[slave] +=
                  c * q.direction_component(system.dof_component(dof));
              }
          }
        own.shares.clear();
        if (children)
          own.shares = children->shares_of(own.combination);
        values[k] = system.row_times(own, unknowns) - system.row_load(own);
        if (shares)
          values[k] += shares->of_row(own);
        for (const auto &[slave, a] : alpha)
          values[k] += a * pair_reactions[pair_row_at.at(slave)];
      }
    if (partition.distributed())
      Utilities::MPI::sum(values, partition.communicator, values);
  }

  std::vector<std::array<double, 3>>
  contact_node_displacements(const EquilibriumSystem &system,
                             const DofPartition      &partition,
                             const FieldVector       &displacement)
  {
    const unsigned int  nq = system.contact_rows.size();
    std::vector<double> node_u(3 * nq, 0.);
    for (unsigned int k = 0; k < nq; ++k)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[k]];
        if (partition.owned.is_element(row.combination.front().first))
          for (unsigned int d = 0; d < system.dim; ++d)
            node_u[3 * k + d] = displacement(row.combination[d].first);
      }
    if (partition.distributed())
      Utilities::MPI::sum(node_u, partition.communicator, node_u);
    std::vector<std::array<double, 3>> result(nq, {{0., 0., 0.}});
    for (unsigned int k = 0; k < nq; ++k)
      for (unsigned int d = 0; d < system.dim; ++d)
        result[k][d] = node_u[3 * k + d];
    return result;
  }
} // namespace hrcontact
