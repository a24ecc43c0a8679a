#include <hrcontact/discretisation/cell_condensation.h>
#include <hrcontact/discretisation/displacement_stiffness.h>
#include <hrcontact/solvers/condensed/condensed_step.h>
#include <hrcontact/solvers/condensed/step_rows.h>

#include <set>

namespace hrcontact
{
  using namespace dealii;

  CondensedStep::~CondensedStep() = default;

  CondensedStep::CondensedStep(const EquilibriumSystem    &system,
                               const LinearSolverSettings &settings,
                               const DofPartition         *given_partition,
                               const CellStiffness        *stiffness)
    : system(system)
    , stiffness(stiffness)
    , partition(given_partition ?
                  *given_partition :
                  serial_partition(system.n_displacement_dofs,
                                   system.cell_stress_dofs.size()))
    , recovery(system, partition)
  {
    const LinearSolverKind solver =
      settings.choose(system.n_displacement_dofs, system.dim);
    statistics.solver    = to_string(solver);
    statistics.iterative = (solver == LinearSolverKind::cg_amg);
    // The recovery cells of a lean system on a distributed mesh are owned or
    // ghost cells: their dofs are relevant. Every cell stored (not lean)
    // would include artificial ones.
    ghosted_u     = partition.distributed_mesh && !system.stored_cell.empty();
    row_ownership = ContactRowPartition(system, partition);
    back_end      = create_condensed_back_end(
      solver, system, settings, partition, ghosted_u, statistics);
    assemble();
  }

  void
  CondensedStep::rows_changed()
  {
    back_end->rows_changed();
  }

  void
  CondensedStep::flexibility_changed()
  {
    back_end->flexibility_changed();
    assemble();
  }

  void
  CondensedStep::assemble()
  {
    const unsigned int n_cells  = system.n_cells();
    unsigned int       n_stored = 0;
    for (unsigned int c = 0; c < n_cells; ++c)
      n_stored += system.is_stored(c);
    // Another bilinear form (stiffness) has no stresses to recover.
    recovery.clear(n_stored, n_stored == n_cells && !stiffness);
    strain_loads.clear();
    back_end->assemble([this](
                         DynamicSparsityPattern &dsp) { add_couplings(dsp); },
                       [this](const CellStiffnessSink &add_owned) {
                         condense_cells(add_owned);
                       });
    recovery.index(!stiffness);
  }

  void
  CondensedStep::condense_cells(const CellStiffnessSink &add_owned)
  {
    auto owned_cell = [&](const unsigned int c) {
      return bool(partition.owned_cell[c]);
    };
    if (stiffness)
      {
        stiffness->for_each_cell(
          owned_cell,
          [&](const unsigned int                          cell,
              const std::vector<types::global_dof_index> &du,
              const FullMatrix<double>                   &K_cell,
              const Vector<double>                       &load) {
            add_owned(cell, du, K_cell);
            // A Newton step's load, kept as a strain load is.
            if (load.size() > 0)
              strain_loads.add(du, load);
          });
        return;
      }
    CellCondensation   condensation;
    FullMatrix<double> R, Kc;
    Vector<double>     shift, cell_load;
    bool               have_factor = false, have_R = false, have_Kc = false;
    system.for_each_cell_blocks(
      [&](const unsigned int c) {
        return owned_cell(c) || system.is_stored(c);
      },
      [&](const CellBlocks &b) {
        const auto &du = b.displacement_dofs;
        // The same B_c and F_c as the previous cell: the same R and K_c.
        if (!(b.same_as_previous && have_factor))
          {
            condensation.factorise(b.F, b.B);
            have_factor = true;
            have_R      = false;
            have_Kc     = false;
          }
        // A material Newton step's strain term: the stresses shift by
        // -F_c^{-1} d_c and the load by B_c F_c^{-1} d_c.
        // Stored cells bring the d_c of the last refresh, recomputed
        // ones that of the same stress state.
        if (b.strain_term.size() > 0)
          condensation.solve(b.strain_term, shift);
        else
          shift.reinit(0);
        if (owned_cell(b.cell))
          {
            if (!have_Kc)
              {
                condensation.stiffness(Kc);
                have_Kc = true;
              }
            add_owned(b.cell, du, Kc);
            if (shift.size() > 0)
              {
                cell_load.reinit(du.size());
                b.B.vmult(cell_load, shift);
                strain_loads.add(du, cell_load);
              }
          }
        if (system.is_stored(b.cell))
          {
            if (!have_R)
              {
                condensation.recovery(R);
                have_R = true;
              }
            recovery.add_cell(b.cell, R, shift);
          }
      });
  }

  void
  CondensedStep::add_couplings(DynamicSparsityPattern &dsp) const
  {
    system.for_each_cell_dofs(
      [&](const unsigned int c) { return bool(partition.owned_cell[c]); },
      [&](const unsigned int, const std::vector<types::global_dof_index> &du) {
        if (system.n_hanging_dofs == 0)
          {
            for (const auto i : du)
              for (const auto j : du)
                dsp.add(i, j);
            return;
          }
        // A hanging dof couples the cell to every dof of its parents'
        // nodes: a held row there may express one component by another.
        std::vector<types::global_dof_index> dofs = du;
        for (const auto i : du)
          if (system.hanging_nodes.is_constrained(i))
            for (const auto &[parent, a] :
                 *system.hanging_nodes.get_constraint_entries(i))
              for (unsigned int d = 0; d < system.dim; ++d)
                dofs.push_back(system.dim * system.dof_node(parent) + d);
        for (const auto i : dofs)
          for (const auto j : dofs)
            dsp.add(i, j);
      });
    // A Q row over the dofs of several nodes (a contact pair) couples
    // them through its spring, and holding it expresses one of them by
    // the others: the entries the condensation fills in are those of
    // every dof coupled to one of the row's with every dof of the row.
    for (const unsigned int r : system.contact_rows)
      {
        const EquilibriumRow &row = system.rows[r];
        if (system.dof_node(row.combination.front().first) ==
            system.dof_node(row.combination.back().first))
          continue;
        std::set<types::global_dof_index> dofs;
        for (const auto &[dof, c] : row.combination)
          dofs.insert(dof);
        std::set<types::global_dof_index> around = dofs;
        for (const auto i : dofs)
          if (dsp.row_index_set().size() == 0 ||
              dsp.row_index_set().is_element(i))
            for (auto it = dsp.begin(i); it != dsp.end(i); ++it)
              around.insert(it->column());
        for (const auto i : around)
          for (const auto j : dofs)
            {
              dsp.add(i, j);
              dsp.add(j, i);
            }
      }
  }

  void
  CondensedStep::solve(const std::vector<ContactPiece> &pieces,
                       std::vector<double>             &p)
  {
    const StepRows rows(system, partition, row_ownership, pieces);
    ++statistics.solves;
    back_end->solve(rows, strain_loads, u);
    recovery.recover(u);
    recovery.contact_reactions(row_ownership, p);
  }

  void
  CondensedStep::stresses(FieldVector &stress) const
  {
    recovery.stresses(u, stress);
  }

  void
  CondensedStep::set_start(const FieldVector &u_start)
  {
    AssertDimension(u_start.size(), system.n_displacement_dofs);
    back_end->set_start(u_start);
  }

  void
  CondensedStep::displacements(const std::vector<double> &,
                               FieldVector &displacement) const
  {
    AssertDimension(displacement.size(), system.n_displacement_dofs);
    if (!is_complete(displacement))
      {
        // A field of the distributed mesh: its owned dofs are this
        // partition's.
        for (const auto i : partition.owned)
          displacement(i) = u(i);
        displacement.update_ghost_values();
      }
    else if (!ghosted_u)
      std::copy(u.begin(), u.end(), displacement.begin());
    else
      {
        // Gathered on every process (the owned dofs are contiguous, so the
        // sum only adds zeros elsewhere).
        displacement = 0;
        for (const auto i : partition.owned)
          displacement(i) = u(i);
        sum_over_processes(displacement, partition.communicator);
      }
  }

  void
  CondensedStep::contact_displacements(std::vector<double> &w) const
  {
    // With u on the relevant dofs only, each row by the owner of its node
    // (whose ghosts hold the node's dofs), the rows of ghost nodes from
    // their owners; with u complete, every row.
    w.assign(system.contact_rows.size(), 0.);
    for (unsigned int i = 0; i < w.size(); ++i)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        if (ghosted_u && !row_ownership.is_owned(i))
          continue;
        for (unsigned int k = 0; k < row.combination.size(); ++k)
          w[i] += row.direction_component(k) * u(row.combination[k].first);
      }
    if (ghosted_u)
      row_ownership.import_ghosts(w);
  }


  bool
  CondensedStep::tighten_linear_solver()
  {
    return back_end->tighten();
  }
} // namespace hrcontact
