#include <deal.II/base/timer.h>

#include <deal.II/lac/sparsity_tools.h>

#include <hrcontact/solvers/condensed/trilinos_back_end.h>

#include <algorithm>

#include <Epetra_CrsMatrix.h>

namespace hrcontact
{
  using namespace dealii;

  TrilinosBackEnd::TrilinosBackEnd(const EquilibriumSystem    &system,
                                   const LinearSolverSettings &settings,
                                   const DofPartition         &partition,
                                   const bool                  ghosted_u,
                                   LinearSolverStatistics     &statistics)
    : system(system)
    , settings(settings)
    , partition(partition)
    , statistics(statistics)
    , ghosted_u(ghosted_u)
  {
    // The AMG's rigid-body modes read each dof's node coordinates.
    AssertThrow(system.node_coordinates.size() * system.dim ==
                  system.n_displacement_dofs,
                ExcMessage("the Trilinos back end needs the node "
                           "coordinates of HRAssembler::classify_rows"));
  }

  template <typename F>
  void
  TrilinosBackEnd::for_each_changing_row(const F &f) const
  {
    const Epetra_CrsMatrix &E = matrix.trilinos_matrix();
    for (const int row : changing_rows)
      {
        int     n = 0;
        double *v = nullptr;
        E.ExtractMyRowView(row, n, v);
        f(v, n);
      }
  }

  std::vector<double>
  TrilinosBackEnd::row_values() const
  {
    std::vector<double> values;
    for_each_changing_row([&](const double *v, const int n) {
      values.insert(values.end(), v, v + n);
    });
    return values;
  }

  void
  TrilinosBackEnd::set_row_values(const std::vector<double> &values) const
  {
    const double *w = values.data();
    for_each_changing_row([&](double *v, const int n) {
      std::copy(w, w + n, v);
      w += n;
    });
  }

  void
  TrilinosBackEnd::swap_row_values(std::vector<double> &values) const
  {
    double *w = values.data();
    for_each_changing_row([&](double *v, const int n) {
      std::swap_ranges(v, v + n, w);
      w += n;
    });
  }

  void
  TrilinosBackEnd::rows_changed()
  {
    assembled = false;
  }

  void
  TrilinosBackEnd::flexibility_changed()
  {
    drop_matrix_dependents();
    assembled = false;
  }

  void
  TrilinosBackEnd::assemble(
    const std::function<void(DynamicSparsityPattern &)>  &couplings,
    const std::function<void(const CellStiffnessSink &)> &cells)
  {
    // The step-40 idiom: the couplings of the owned cells, sent to the
    // owners of their rows. The pattern comes from the cells' dofs
    // alone, so that no K_c is buffered: each goes straight into the
    // fixed part of K or, at a Q or H row, into the kept cells (on a
    // 3D mesh the buffer of every owned K_c was 4.6 KB a cell).
    // The pattern depends on the mesh and the rows only: a material
    // Newton step (new F_c) refills the same matrix, which also lets a
    // direct solver keep its symbolic factorisation (TrilinosMumps).
    if (pattern_built)
      {
        matrix = 0.;
        x      = 0.;
      }
    else
      {
        DynamicSparsityPattern dsp(partition.relevant);
        couplings(dsp);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   partition.owned,
                                                   partition.communicator,
                                                   partition.relevant);
        matrix.reinit(partition.owned,
                      partition.owned,
                      dsp,
                      partition.communicator);
        rhs.reinit(partition.owned, partition.communicator);
        x.reinit(partition.owned, partition.communicator);
        pattern_built = true;
      }
    // The cells at Q and H rows are kept (also those around a hanging node
    // whose parent has one: it follows the held rows); every other cell
    // goes into the fixed part of K, through the hanging nodes'
    // constraints where it has one.
    std::vector<bool> at_row(system.n_displacement_dofs, false);
    for (const auto *rows : {&system.contact_rows, &system.prescribed_rows})
      for (const unsigned int r : *rows)
        for (const auto *terms :
             {&system.rows[r].combination, &system.rows[r].shares})
          for (const auto &[dof, c] : *terms)
            at_row[dof] = true;
    auto                                &fixed = matrix;
    std::vector<types::global_dof_index> kept_dofs;
    std::vector<double>                  kept_stiffness;
    unsigned int                         n_per_cell = 0;
    cells([&](const unsigned int,
              const std::vector<types::global_dof_index> &du,
              const FullMatrix<double>                   &K_cell) {
      n_per_cell = du.size(); // every cell has as many dofs
      if (std::any_of(du.begin(), du.end(), [&](const auto i) {
            return at_row[i];
          }))
        {
          kept_dofs.insert(kept_dofs.end(), du.begin(), du.end());
          for (unsigned int i = 0; i < du.size(); ++i)
            for (unsigned int j = 0; j < du.size(); ++j)
              kept_stiffness.push_back(K_cell(i, j));
          return;
        }
      if (system.n_hanging_dofs > 0)
        system.hanging_nodes.distribute_local_to_global(K_cell, du, fixed);
      else
        fixed.add(du, K_cell);
    });
    fixed.compress(VectorOperation::add);

    // The rows the kept cells add to, marked by the processes that own
    // the cells and summed to the rows' owners, and their fixed values.
    TrilinosWrappers::MPI::Vector changing;
    changing.reinit(partition.owned,
                    partition.relevant,
                    partition.communicator,
                    true);
    changing.add(std::vector<types::global_dof_index>(kept_dofs.begin(),
                                                      kept_dofs.end()),
                 std::vector<double>(kept_dofs.size(), 1.));
    // A kept cell's hanging dof adds to its parents' rows, which need not
    // be the cell's own.
    if (system.n_hanging_dofs > 0)
      for (const auto i : kept_dofs)
        if (system.hanging_nodes.is_constrained(i))
          for (const auto &[parent, a] :
               *system.hanging_nodes.get_constraint_entries(i))
            changing.add(std::vector<types::global_dof_index>{parent},
                         std::vector<double>{1.});
    // A held contact pair row condenses its slave's couplings into the
    // master's rows, on whichever process owns them.
    for (const unsigned int r : system.contact_rows)
      {
        const EquilibriumRow &row = system.rows[r];
        if (system.dof_node(row.combination.front().first) ==
              system.dof_node(row.combination.back().first) ||
            !partition.owned.is_element(row.combination.front().first))
          continue;
        for (const auto &[dof, c] : row.combination)
          changing.add(std::vector<types::global_dof_index>{dof},
                       std::vector<double>{1.});
      }
    changing.compress(VectorOperation::add);
    const Epetra_Map &map = fixed.trilinos_matrix().RowMap();
    changing_rows.clear();
    for (const auto i : partition.owned)
      if (changing[i] != 0)
        changing_rows.push_back(
          map.LID(static_cast<TrilinosWrappers::types::int_type>(i)));
    fixed_values   = row_values();
    dofs_per_cell  = n_per_cell;
    cell_dofs      = std::move(kept_dofs);
    cell_stiffness = std::move(kept_stiffness);
  }

  void
  TrilinosBackEnd::assemble_step(const StepRows    &rows,
                                 const StrainLoads &loads,
                                 const bool         same_matrix)
  {
    const auto &constraints = rows.constraints;
    auto        distribute  = [&](const FullMatrix<double>                   &M,
                          const Vector<double>                       &f,
                          const std::vector<types::global_dof_index> &dofs) {
      if (same_matrix)
        constraints.distribute_local_to_global(f, dofs, rhs, M);
      else
        constraints.distribute_local_to_global(M, f, dofs, matrix, rhs);
    };
    // Loads enter per dof below; the cells at Q and H rows bring
    // stiffness only.
    const unsigned int n_per_cell = dofs_per_cell;
    const std::size_t  n_owned_cells =
      (n_per_cell == 0) ? 0 : cell_dofs.size() / n_per_cell;
    Vector<double>                       no_cell_force(n_per_cell);
    FullMatrix<double>                   Kc(n_per_cell, n_per_cell);
    std::vector<types::global_dof_index> du(n_per_cell);
    for (std::size_t k = 0; k < n_owned_cells; ++k)
      {
        const std::size_t first = std::size_t(k) * n_per_cell;
        std::copy(cell_dofs.begin() + first,
                  cell_dofs.begin() + first + n_per_cell,
                  du.begin());
        const double *values = cell_stiffness.data() + first * n_per_cell;
        for (unsigned int i = 0; i < n_per_cell; ++i)
          for (unsigned int j = 0; j < n_per_cell; ++j)
            Kc(i, j) = values[i * n_per_cell + j];
        no_cell_force = 0;
        distribute(Kc, no_cell_force, du);
      }
    FullMatrix<double>                   spring_matrix;
    Vector<double>                       spring_force;
    std::vector<types::global_dof_index> node_dofs;
    for (const Spring &spring : rows.springs)
      {
        spring.matrix_and_force(spring_matrix, spring_force);
        node_dofs.clear();
        for (const auto &[dof, c] : spring.row->combination)
          node_dofs.push_back(dof);
        distribute(spring_matrix, spring_force, node_dofs);
      }
    loads.for_each([&](const std::vector<types::global_dof_index> &dofs,
                       const Vector<double>                       &values) {
      constraints.distribute_local_to_global(values, dofs, rhs);
    });
    Vector<double>                       one_load(1);
    std::vector<types::global_dof_index> one_dof(1);
    for (const auto i : partition.owned)
      if (system.load[i] != 0)
        {
          one_load[0] = system.load[i];
          one_dof[0]  = i;
          constraints.distribute_local_to_global(one_load, one_dof, rhs);
        }
  }

  void
  TrilinosBackEnd::solve(const StepRows    &rows,
                         const StrainLoads &loads,
                         FieldVector       &u)
  {
    Timer timer;
    rhs = 0;
    // The same held rows and springs as the matrix has (a multiplier
    // update with no branch or penalty changed): the right-hand side
    // only, the constraints' inhomogeneities eliminated with the kept
    // cells' and springs' matrices as the assembly with the matrix does;
    // and what the back end built on the matrix stays valid. Whether the
    // matrix stays is agreed on by all (its assembly is collective).
    const bool same_matrix =
      Utilities::MPI::min(int(assembled && matrix_key == rows.key),
                          partition.communicator) == 1;
    if (!same_matrix)
      {
        // The rows the last step changed go back to the fixed part of K.
        set_row_values(fixed_values);
        matrix_changing();
      }
    assemble_step(rows, loads, same_matrix);
    if (!same_matrix)
      {
        matrix.compress(VectorOperation::add);
        matrix_key = rows.key;
        assembled  = true;
      }
    rhs.compress(VectorOperation::add);
    statistics.setup_seconds += timer.wall_time();

    if (!settings.warm_start)
      x = 0;
    else
      {
        // The last solution carries the held values in its constrained
        // entries (distribute), where this system's decoupled rows ask
        // for zero: left there, they would start CG with a residual as
        // large as their diagonal forces (Hertz refinement 8: 0.67 of
        // the right-hand side instead of 1e-8).
        for (const auto &line : rows.constraints.get_lines())
          if (x.in_local_range(line.index))
            x(line.index) = 0;
        x.compress(VectorOperation::insert);
      }
    solve_assembled();
    rows.constraints.distribute(x);
    // The owned dofs, and the ghosts from their owners; or every dof on
    // every process (see ghosted_u).
    if (ghosted_u)
      u.reinit(partition.owned, partition.relevant, partition.communicator);
    else
      u.reinit(system.n_displacement_dofs);
    for (const auto i : partition.owned)
      u(i) = x[i];
    if (ghosted_u)
      u.update_ghost_values();
    else if (partition.distributed())
      sum_over_processes(u, partition.communicator);
  }
} // namespace hrcontact
