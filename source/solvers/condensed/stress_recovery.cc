#include <hrcontact/discretisation/cell_condensation.h>
#include <hrcontact/solvers/condensed/stress_recovery.h>

#include <map>

namespace hrcontact
{
  using namespace dealii;

  StressRecovery::StressRecovery(const EquilibriumSystem &system,
                                 const DofPartition      &partition)
    : system(system)
    , partition(partition)
  {}

  void
  StressRecovery::clear(const unsigned int n_recovery_cells,
                        const bool         every_cell)
  {
    cells.clear();
    recovery.clear();
    shift.clear();
    cells.reserve(n_recovery_cells);
    recovery.reserve(n_recovery_cells);
    complete = every_cell;
    n_added  = 0;
  }

  void
  StressRecovery::add_cell(const unsigned int        cell,
                           const FullMatrix<double> &R,
                           const Vector<double>     &cell_shift)
  {
    cells.push_back(cell);
    recovery.push_back(R);
    if (cell_shift.size() > 0)
      {
        // Zeros for the cells before the first with a term.
        shift.resize(n_added, 0.);
        shift.insert(shift.end(), cell_shift.begin(), cell_shift.end());
      }
    n_added += system.cell_stress_dofs[cell].size();
  }

  void
  StressRecovery::index(const bool with_rows)
  {
    offset.assign(1, 0);
    for (const unsigned int c : cells)
      offset.push_back(offset.back() + system.cell_stress_dofs[c].size());
    stress.assign(offset.back(), 0.);
    // Zeros for the recovery cells after the last with a strain term.
    if (!shift.empty())
      shift.resize(offset.back(), 0.);

    // The stress dofs the owned Q rows read, and where each is recovered
    // (a row's B entries belong to the cells around its node, all of them
    // recovery cells: the stored cells).
    const std::size_t none      = numbers::invalid_size_type;
    auto              owned_row = [&](const EquilibriumRow &row) {
      return partition.owned.is_element(row.combination.front().first);
    };
    std::map<types::global_dof_index, std::size_t> position;
    for (const unsigned int r : system.contact_rows)
      if (owned_row(system.rows[r]))
        for (const auto &[dof, c] : system.rows[r].combination)
          if (c != 0) // a contact pair's master entries
            for (auto it = system.B.begin(system.b_row(dof));
                 it != system.B.end(system.b_row(dof));
                 ++it)
              position.emplace(it->column(), none);
    for (unsigned int k = 0; k < cells.size(); ++k)
      {
        const auto &ds = system.cell_stress_dofs[cells[k]];
        for (unsigned int j = 0; j < ds.size(); ++j)
          {
            const auto found = position.find(ds[j]);
            if (found != position.end())
              found->second = offset[k] + j;
          }
      }

    terms.clear();
    term_start.assign(1, 0);
    for (const unsigned int r : system.contact_rows)
      {
        const EquilibriumRow &row = system.rows[r];
        if (owned_row(row) && with_rows)
          for (unsigned int k = 0; k < row.combination.size(); ++k)
            {
              const auto dof = row.combination[k].first;
              if (row.combination[k].second == 0)
                continue;
              for (auto it = system.B.begin(system.b_row(dof));
                   it != system.B.end(system.b_row(dof));
                   ++it)
                {
                  const std::size_t at = position.at(it->column());
                  AssertThrow(at != none,
                              ExcInternalError("a Q row reads the stresses "
                                               "of a cell not recovered"));
                  terms.push_back({k, at, it->value()});
                }
            }
        term_start.push_back(terms.size());
      }

    share_forces.reset();
    share_position.clear();
    if (with_rows && system.n_hanging_dofs > 0)
      {
        share_forces = std::make_unique<HangingShareForces>(system, partition);
        std::map<types::global_dof_index, std::size_t> at;
        for (const auto &term : share_forces->terms())
          at.emplace(term.column, none);
        for (unsigned int k = 0; k < cells.size(); ++k)
          {
            const auto &ds = system.cell_stress_dofs[cells[k]];
            for (unsigned int j = 0; j < ds.size(); ++j)
              {
                const auto found = at.find(ds[j]);
                if (found != at.end())
                  found->second = offset[k] + j;
              }
          }
        for (const auto &term : share_forces->terms())
          {
            share_position.push_back(at.at(term.column));
            AssertThrow(share_position.back() != none,
                        ExcInternalError("a hanging share reads the stresses "
                                         "of a cell not recovered"));
          }
      }
  }

  void
  StressRecovery::recover(const FieldVector &u)
  {
    for (unsigned int k = 0; k < cells.size(); ++k)
      {
        const auto &du = system.cell_displacement_dofs[cells[k]];
        double     *s  = stress.data() + offset[k];
        const auto  n  = offset[k + 1] - offset[k];
        for (unsigned int i = 0; i < n; ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < du.size(); ++j)
              sum += recovery[k](i, j) * u[du[j]];
            s[i] = sum;
          }
        if (!shift.empty())
          for (unsigned int i = 0; i < n; ++i)
            s[i] -= shift[offset[k] + i];
      }
  }

  void
  StressRecovery::contact_reactions(const ContactRowPartition &rows,
                                    std::vector<double>       &p) const
  {
    // p of each row by the owner of its node, the only process that has
    // every cell around it on a distributed mesh; the rows of ghost nodes
    // from their owners.
    p.assign(system.contact_rows.size(), 0.);
    if (share_forces)
      share_forces->evaluate(
        [&](const std::size_t k) { return stress[share_position[k]]; });
    for (const unsigned int i : rows.owned())
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        double                sum = 0;
        for (std::size_t t = term_start[i]; t < term_start[i + 1]; ++t)
          {
            const StressTerm &term = terms[t];
            sum +=
              row.combination[term.k].second * term.b * stress[term.position];
          }
        if (share_forces)
          sum += share_forces->of_row(row);
        p[i] = sum - system.row_load(row);
      }
    rows.import_ghosts(p);
  }

  void
  StressRecovery::stresses(const FieldVector &u, FieldVector &field) const
  {
    // Every process recovers its own cells, the stored ones from their kept
    // F_c^{-1} B_c^T (already done by the last solve), the others (a lean
    // system) from recomputed blocks, in the same operations. The stress
    // dofs of a cell are its own: on a distributed mesh the owner of the cell
    // owns them, and its ghost cells' entries come from their owners; a
    // complete vector (a serial mesh under MPI) is the sum over the
    // processes.
    AssertDimension(field.size(), system.n_stress_dofs);
    field = 0;
    for (unsigned int k = 0; k < cells.size(); ++k)
      if (partition.owned_cell[cells[k]])
        {
          const auto &ds = system.cell_stress_dofs[cells[k]];
          for (unsigned int j = 0; j < ds.size(); ++j)
            field(ds[j]) = stress[offset[k] + j];
        }
    if (!complete)
      {
        CellCondensation condensation;
        bool             have_factor = false;
        Vector<double>   y, s_c;
        system.for_each_cell_blocks(
          [&](const unsigned int c) {
            return partition.owned_cell[c] && !system.is_stored(c);
          },
          [&](const CellBlocks &b) {
            const auto &du = b.displacement_dofs;
            const auto &ds = b.stress_dofs;
            if (!(b.same_as_previous && have_factor))
              condensation.factorise(b.F);
            have_factor = true;
            // s_c = F_c^{-1} (B_c^T u - d_c), d_c a material Newton step's
            // strain term.
            y.reinit(ds.size());
            for (unsigned int i = 0; i < ds.size(); ++i)
              {
                double sum = 0;
                for (unsigned int j = 0; j < du.size(); ++j)
                  sum += b.B(j, i) * u[du[j]];
                y[i] = sum - (b.strain_term.size() > 0 ? b.strain_term[i] : 0.);
              }
            condensation.solve(y, s_c);
            for (unsigned int i = 0; i < ds.size(); ++i)
              field(ds[i]) = s_c[i];
          });
      }
    if (!is_complete(field))
      field.update_ghost_values();
    else if (partition.distributed())
      sum_over_processes(field, partition.communicator);
  }
} // namespace hrcontact
