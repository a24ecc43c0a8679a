#include <deal.II/base/timer.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/cell_condensation.h>
#include <hrcontact/discretisation/displacement_stiffness.h>
#include <hrcontact/solvers/newton_step.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>

namespace hrcontact
{
  using namespace dealii;

  /** The Trilinos back end of the condensed path. */
  struct CondensedStep::Distributed
  {
    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs, u;
    /**
     * With Reuse preconditioner: the values of changing_rows when the kept
     * AMG hierarchy was built. ML keeps a pointer to `matrix` and applies
     * its finest level with the values there, so they are swapped in for
     * each application of the preconditioner and out again for CG's own
     * products (AtSetupValues): a surface of rows, where a copy of the
     * whole matrix was kept before, with the same arithmetic.
     */
    std::vector<double>                 setup_values;
    TrilinosWrappers::PreconditionAMG   preconditioner;
    std::unique_ptr<Epetra_MultiVector> modes;
    /** Per owned node, its coordinates (x, y, z), for coordinate
     * aggregation; ML reads them during the set-up. */
    std::array<std::vector<double>, 3> node_xyz;
    bool                               built                  = false;
    unsigned int                       iterations_after_setup = 0;
    /**
     * The part of K that no Newton step changes is K_c summed over the owned
     * cells none of whose dofs belongs to the node of a Q or H row (held
     * rows, springs and their constraints touch only the cells at those
     * nodes). It is assembled once into `matrix`; a step changes only the
     * rows of the kept cells' dofs, so it restores their fixed values (kept
     * here, row after row, with Epetra's local row numbers) and adds the
     * kept cells, instead of copying a second matrix of the fixed part: one
     * matrix fewer per process, and the same values to the last bit.
     */
    std::vector<int>    changing_rows;
    std::vector<double> fixed_values;

    /** f(values, n) on the stored values of each of changing_rows. */
    template <typename F>
    void
    for_each_changing_row(const F &f) const
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

    /** The values of changing_rows, row after row. */
    std::vector<double>
    row_values() const
    {
      std::vector<double> values;
      for_each_changing_row([&](const double *v, const int n) {
        values.insert(values.end(), v, v + n);
      });
      return values;
    }

    /** Write @p values (row_values' layout) into changing_rows. */
    void
    set_row_values(const std::vector<double> &values) const
    {
      const double *w = values.data();
      for_each_changing_row([&](double *v, const int n) {
        std::copy(w, w + n, v);
        w += n;
      });
    }

    /** Exchange the values of changing_rows with those in @p values. */
    void
    swap_row_values(std::vector<double> &values) const
    {
      double *w = values.data();
      for_each_changing_row([&](double *v, const int n) {
        std::swap_ranges(v, v + n, w);
        w += n;
      });
    }

    /**
     * The kept AMG hierarchy, applied with the matrix values it was built
     * from: swapped into the changing rows for the application and back
     * out for CG's own product with the current matrix.
     */
    struct AtSetupValues
    {
      Distributed &d;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        d.swap_row_values(d.setup_values);
        d.preconditioner.vmult(dst, src);
        d.swap_row_values(d.setup_values);
      }
    };
    /** The displacement dofs and K_c of the other owned cells, those at Q
     * and H rows, one cell after the other (dofs_per_cell and its square
     * numbers each). */
    unsigned int                         dofs_per_cell = 0;
    std::vector<types::global_dof_index> cell_dofs;
    std::vector<double>                  cell_stiffness;
    /**
     * The held rows and springs `matrix` was assembled for (the key of
     * CondensedStep::solve, as for the direct factor). A multiplier update
     * that keeps every branch and penalty changes only the right-hand side:
     * the next step keeps the matrix and its AMG hierarchy.
     */
    std::vector<double> matrix_key;
    bool                assembled = false;
    /**
     * The MUMPS factor of `matrix` (Solver = direct with more than one
     * process), kept while the matrix is: a step that changes only the
     * right-hand side costs a forward and back substitution, as with the
     * serial path's UMFPACK factor. Amesos keeps a pointer to `matrix` and
     * the solver one to its control.
     */
    std::unique_ptr<SolverControl>                  direct_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct_solver;
  };

  // ------------------------------------------------------------------------
  // Null-space path

  NullSpaceStep::NullSpaceStep(EquilibriumReduction &reduction)
    : reduction(reduction)
  {
    // The dense path runs whole on every process: every row is its own.
    row_ownership = ContactRowPartition(reduction.n_contact_rows());
    prepare();
  }

  void
  NullSpaceStep::flexibility_changed()
  {
    reduction.flexibility_changed();
    prepare();
  }

  void
  NullSpaceStep::prepare()
  {
    const unsigned int nq = reduction.n_contact_rows();
    const unsigned int m  = reduction.n_self_equilibrated();
    Z.resize(static_cast<std::size_t>(m) * nq);
    for (unsigned int i = 0; i < nq; ++i)
      std::copy(reduction.QR_row(i),
                reduction.QR_row(i) + m,
                Z.begin() + static_cast<std::size_t>(i) * m);
    reduction.solve_M0(Z.data(), nq);
    S.reinit(nq, nq);
    for (unsigned int i = 0; i < nq; ++i)
      for (unsigned int j = 0; j < nq; ++j)
        {
          const double *q   = reduction.QR_row(i);
          const double *z   = Z.data() + static_cast<std::size_t>(j) * m;
          double        sum = 0;
          for (unsigned int k = 0; k < m; ++k)
            sum += q[k] * z[k];
          S(i, j) = sum;
        }
  }

  void
  NewtonStepPath::solve(const std::vector<bool>   &released,
                        const std::vector<double> &mu,
                        const std::vector<double> &alpha,
                        std::vector<double>       &p)
  {
    std::vector<ContactPiece> pieces(released.size());
    for (unsigned int i = 0; i < released.size(); ++i)
      if (released[i])
        {
          pieces[i].spring     = true;
          pieces[i].offset     = mu[i];
          pieces[i].compliance = alpha[i];
        }
    solve(pieces, p);
  }

  void
  NullSpaceStep::solve(const std::vector<ContactPiece> &pieces,
                       std::vector<double>             &p)
  {
    const unsigned int        nq = reduction.n_contact_rows();
    const unsigned int        m  = reduction.n_self_equilibrated();
    const auto               &a  = reduction.contact_offset();
    std::vector<unsigned int> active;
    std::vector<double>       alpha(nq, 0.);
    for (unsigned int i = 0; i < nq; ++i)
      if (pieces[i].spring)
        {
          if (!std::isfinite(pieces[i].compliance))
            throw InputError(
              "the null-space path cannot solve a row without stiffness "
              "(an infinite compliance); take Equilibrium reduction/Path = "
              "condensed.");
          active.push_back(i);
          alpha[i] = pieces[i].compliance;
        }

    // H s0 = r, H = M0 + sum_A alpha_i q_i q_i^T,
    // r = b0 + sum_A q_i (offset_i - alpha_i a_i) + sum_held q_i offset_i:
    // the row's term of the functional is offset p - alpha/2 p^2 (a held
    // row: offset p, which moves its w_n from g to g + offset).
    Vector<double> r = reduction.linear_term();
    for (unsigned int i = 0; i < nq; ++i)
      if (pieces[i].spring || pieces[i].offset != 0)
        {
          const double  c = pieces[i].offset - alpha[i] * a[i];
          const double *q = reduction.QR_row(i);
          for (unsigned int j = 0; j < m; ++j)
            r[j] += c * q[j];
        }
    auto q_dot = [&](const unsigned int i, const Vector<double> &x) {
      const double *q   = reduction.QR_row(i);
      double        sum = 0;
      for (unsigned int j = 0; j < m; ++j)
        sum += q[j] * x[j];
      return sum;
    };
    // Woodbury: H^{-1} v = y - Z_A (alpha_A^{-1} + S_AA)^{-1} (QR_A y),
    // y = M0^{-1} v; W is factorised once per solve.
    const unsigned int       na = active.size();
    LAPACKFullMatrix<double> W(na, na);
    if (na > 0)
      {
        for (unsigned int i = 0; i < na; ++i)
          {
            for (unsigned int j = 0; j < na; ++j)
              W(i, j) = S(active[i], active[j]);
            W(i, i) += 1. / alpha[active[i]];
          }
        W.set_property(LAPACKSupport::symmetric);
        W.compute_cholesky_factorization();
      }
    auto apply_H_inverse = [&](Vector<double> &x) {
      reduction.solve_M0(x.data());
      if (na == 0)
        return;
      Vector<double> t(na);
      for (unsigned int i = 0; i < na; ++i)
        t[i] = q_dot(active[i], x);
      W.solve(t);
      for (unsigned int i = 0; i < na; ++i)
        {
          const double *z = Z.data() + static_cast<std::size_t>(active[i]) * m;
          for (unsigned int j = 0; j < m; ++j)
            x[j] -= t[i] * z[j];
        }
    };
    s0 = r;
    apply_H_inverse(s0);
    // Iterative refinement: compliant springs (large alpha against the
    // nodal compliance) make p a small difference of large numbers; two
    // corrections with the residual r - H s0 bring it to round-off.
    for (unsigned int refinement = 0; refinement < 2; ++refinement)
      {
        Vector<double> residual(m), Hs0(m);
        reduction.multiply_M0(s0, Hs0);
        for (const unsigned int i : active)
          {
            const double  c = alpha[i] * q_dot(i, s0);
            const double *q = reduction.QR_row(i);
            for (unsigned int j = 0; j < m; ++j)
              Hs0[j] += c * q[j];
          }
        residual = r;
        residual -= Hs0;
        apply_H_inverse(residual);
        s0 += residual;
      }
    p.resize(nq);
    for (unsigned int i = 0; i < nq; ++i)
      {
        const double *q   = reduction.QR_row(i);
        double        sum = a[i];
        for (unsigned int j = 0; j < m; ++j)
          sum += q[j] * s0[j];
        p[i] = sum;
      }
  }

  void
  NullSpaceStep::stresses(FieldVector &s) const
  {
    AssertThrow(is_complete(s),
                ExcMessage("the null-space path runs on a serial mesh"));
    Vector<double> complete;
    reduction.stress_from_s0(s0, complete);
    AssertDimension(complete.size(), s.size());
    std::copy(complete.begin(), complete.end(), s.begin());
  }

  void
  NullSpaceStep::displacements(const std::vector<double> &contact_w,
                               FieldVector               &u) const
  {
    AssertThrow(is_complete(u),
                ExcMessage("the null-space path runs on a serial mesh"));
    Vector<double> s, complete;
    reduction.stress_from_s0(s0, s);
    // Eq. 50-51.
    reduction.system_displacements(s, contact_w, complete);
    AssertDimension(complete.size(), u.size());
    std::copy(complete.begin(), complete.end(), u.begin());
  }

  // ------------------------------------------------------------------------
  // Condensed path

  namespace
  {
    const std::string singular_stiffness_message =
      "Condensed path: the stiffness B F^-1 B^T with the current supports is "
      "singular: the body has a zero-energy mode (a mechanism, an unsupported "
      "body, or a stress space too poor for the mesh). The null-space path "
      "(Equilibrium reduction/Path = null-space) names the nodes the mode "
      "moves.";

  } // namespace

  struct CondensedStep::DirectFactor
  {
    /** Per Q row: -1 held, else the spring's compliance; its direction. */
    std::vector<double> key;
    SparseDirectUMFPACK factor;
  };

  CondensedStep::~CondensedStep() = default;

  CondensedStep::CondensedStep(const EquilibriumSystem    &system,
                               const LinearSolverSettings &settings,
                               const DofPartition         *given_partition,
                               const CellStiffness        *stiffness)
    : system(system)
    , settings(settings)
    , stiffness(stiffness)
    , partition(given_partition ?
                  *given_partition :
                  serial_partition(system.n_displacement_dofs,
                                   system.cell_stress_dofs.size()))
  {
    const unsigned int n_u = system.n_displacement_dofs;
    solver                 = settings.choose(n_u, system.dim);
    statistics.solver      = to_string(solver);
    statistics.iterative   = (solver == LinearSolverKind::cg_amg);
    cg_tolerance           = settings.tolerance;
    if (statistics.iterative)
      statistics.tolerance = cg_tolerance;
    if (statistics.iterative || partition.distributed())
      {
        // The AMG's rigid-body modes read each dof's node coordinates.
        AssertThrow(system.node_coordinates.size() * system.dim == n_u,
                    ExcMessage("the Trilinos back end needs the node "
                               "coordinates of HRAssembler::classify_rows"));
        distributed = std::make_unique<Distributed>();
      }
    // The recovery cells of a lean system on a distributed mesh are owned or
    // ghost cells: their dofs are relevant. Every cell stored (not lean)
    // would include artificial ones.
    ghosted_u     = partition.distributed_mesh && !system.stored_cell.empty();
    row_ownership = ContactRowPartition(system, partition);

    assemble();
  }

  void
  CondensedStep::rows_changed()
  {
    direct_factor.reset();
    if (distributed)
      distributed->assembled = false;
  }

  void
  CondensedStep::flexibility_changed()
  {
    direct_factor.reset();
    // ML keeps a pointer to the matrix that assemble() replaces: drop the
    // hierarchy first; the next solve builds one for the new K.
    if (distributed)
      {
        distributed->preconditioner.clear();
        distributed->direct_solver.reset();
        distributed->built     = false;
        distributed->assembled = false;
      }
    assemble();
  }

  void
  CondensedStep::assemble()
  {
    const unsigned int n_u     = system.n_displacement_dofs;
    const unsigned int n_cells = system.n_cells();
    recovery_cells.clear();
    recovery.clear();
    recovered_shift.clear();
    strain_load_dofs.clear();
    strain_load_values.clear();
    unsigned int n_stored = 0;
    for (unsigned int c = 0; c < n_cells; ++c)
      n_stored += system.is_stored(c);
    recovery_complete = (n_stored == n_cells);
    recovery_cells.reserve(n_stored);
    recovery.reserve(n_stored);
    auto owned_cell = [&](const unsigned int c) {
      return bool(partition.owned_cell[c]);
    };
    // One pass over the cells this process owns and those whose stresses
    // every step needs, from the stored blocks or recomputed (a lean
    // system): K_c = B_c F_c^{-1} B_c^T of the owned cells to `add_owned`,
    // and F_c^{-1} B_c^T of the stored cells kept.
    CellCondensation   condensation;
    FullMatrix<double> R, Kc;
    Vector<double>     shift, cell_load;
    std::size_t        stress_count = 0; // of the recovery cells so far
    bool               have_factor = false, have_R = false, have_Kc = false;
    // A cell's load beside K_c (strain_load_*), cell after cell.
    const auto keep_cell_load =
      [&](const std::vector<types::global_dof_index> &du,
          const Vector<double>                       &load) {
        strain_load_cell_size = du.size(); // the same for all
        strain_load_dofs.insert(strain_load_dofs.end(), du.begin(), du.end());
        strain_load_values.insert(strain_load_values.end(),
                                  load.begin(),
                                  load.end());
      };
    auto each_cell =
      [&](const std::function<void(const unsigned int,
                                   const std::vector<types::global_dof_index> &,
                                   const FullMatrix<double> &)> &add_owned) {
        if (stiffness)
          {
            // Another bilinear form: no stresses to recover.
            recovery_complete = false;
            stiffness->for_each_cell(
              owned_cell,
              [&](const unsigned int                          cell,
                  const std::vector<types::global_dof_index> &du,
                  const FullMatrix<double>                   &K_cell,
                  const Vector<double>                       &load) {
                add_owned(cell, du, K_cell);
                // A Newton step's load, kept as a strain load is.
                if (load.size() > 0)
                  keep_cell_load(du, load);
              });
            return;
          }
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
                    keep_cell_load(du, cell_load);
                  }
              }
            if (system.is_stored(b.cell))
              {
                recovery_cells.push_back(b.cell);
                if (!have_R)
                  {
                    condensation.recovery(R);
                    have_R = true;
                  }
                recovery.push_back(R);
                if (shift.size() > 0)
                  {
                    // Zeros for the cells before the first with a term.
                    recovered_shift.resize(stress_count, 0.);
                    recovered_shift.insert(recovered_shift.end(),
                                           shift.begin(),
                                           shift.end());
                  }
                stress_count += b.stress_dofs.size();
              }
          });
      };

    // The couplings of the owned cells, from their dofs alone, so that no
    // K_c is buffered for the pattern.
    auto add_couplings = [&](DynamicSparsityPattern &dsp) {
      system.for_each_cell_dofs(
        owned_cell,
        [&](const unsigned int,
            const std::vector<types::global_dof_index> &du) {
          for (const auto i : du)
            for (const auto j : du)
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
    };

    if (distributed)
      {
        // The step-40 idiom: the couplings of the owned cells, sent to the
        // owners of their rows. The pattern comes from the cells' dofs
        // alone, so that no K_c is buffered: each goes straight into the
        // fixed part of K or, at a Q or H row, into the kept cells (on a
        // 3D mesh the buffer of every owned K_c was 4.6 KB a cell).
        DynamicSparsityPattern dsp(partition.relevant);
        add_couplings(dsp);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   partition.owned,
                                                   partition.communicator,
                                                   partition.relevant);
        distributed->matrix.reinit(partition.owned,
                                   partition.owned,
                                   dsp,
                                   partition.communicator);
        dsp.reinit(0, 0);
        distributed->rhs.reinit(partition.owned, partition.communicator);
        distributed->u.reinit(partition.owned, partition.communicator);
        // The cells at Q and H rows are kept; every other cell goes into the
        // fixed part of K.
        std::vector<bool> at_row(n_u, false);
        for (const auto *rows : {&system.contact_rows, &system.prescribed_rows})
          for (const unsigned int r : *rows)
            for (const auto &[dof, c] : system.rows[r].combination)
              at_row[dof] = true;
        auto                                &fixed = distributed->matrix;
        std::vector<types::global_dof_index> kept_dofs;
        std::vector<double>                  kept_stiffness;
        unsigned int                         n_per_cell = 0;
        each_cell([&](const unsigned int,
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
        const Epetra_Map &rows = fixed.trilinos_matrix().RowMap();
        distributed->changing_rows.clear();
        for (const auto i : partition.owned)
          if (changing[i] != 0)
            distributed->changing_rows.push_back(
              rows.LID(static_cast<TrilinosWrappers::types::int_type>(i)));
        distributed->fixed_values   = distributed->row_values();
        distributed->dofs_per_cell  = n_per_cell;
        distributed->cell_dofs      = std::move(kept_dofs);
        distributed->cell_stiffness = std::move(kept_stiffness);
        index_recovered_stresses();
        return;
      }

    // The serial direct back end: the same two passes into K.
    {
      DynamicSparsityPattern dsp(n_u, n_u);
      add_couplings(dsp);
      sparsity.copy_from(dsp);
    }
    K.reinit(sparsity);
    each_cell([&](const unsigned int,
                  const std::vector<types::global_dof_index> &du,
                  const FullMatrix<double> &K_cell) { K.add(du, K_cell); });
    index_recovered_stresses();
  }

  void
  CondensedStep::add_strain_loads(
    const std::function<void(const std::vector<types::global_dof_index> &,
                             const Vector<double> &)> &add) const
  {
    if (strain_load_dofs.empty())
      return;
    const std::size_t n = strain_load_cell_size;
    AssertThrow(n > 0 && strain_load_dofs.size() % n == 0, ExcInternalError());
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       values(n);
    for (std::size_t first = 0; first < strain_load_dofs.size(); first += n)
      {
        std::copy(strain_load_dofs.begin() + first,
                  strain_load_dofs.begin() + first + n,
                  dofs.begin());
        std::copy(strain_load_values.begin() + first,
                  strain_load_values.begin() + first + n,
                  values.begin());
        add(dofs, values);
      }
  }

  void
  CondensedStep::index_recovered_stresses()
  {
    recovered_offset.assign(1, 0);
    for (const unsigned int c : recovery_cells)
      recovered_offset.push_back(recovered_offset.back() +
                                 system.cell_stress_dofs[c].size());
    recovered_stress.assign(recovered_offset.back(), 0.);
    // Zeros for the recovery cells after the last with a strain term.
    if (!recovered_shift.empty())
      recovered_shift.resize(recovered_offset.back(), 0.);

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
    for (unsigned int k = 0; k < recovery_cells.size(); ++k)
      {
        const auto &ds = system.cell_stress_dofs[recovery_cells[k]];
        for (unsigned int j = 0; j < ds.size(); ++j)
          {
            const auto found = position.find(ds[j]);
            if (found != position.end())
              found->second = recovered_offset[k] + j;
          }
      }

    contact_terms.clear();
    contact_term_start.assign(1, 0);
    for (const unsigned int r : system.contact_rows)
      {
        const EquilibriumRow &row = system.rows[r];
        if (owned_row(row) && !stiffness)
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
                  contact_terms.push_back({k, at, it->value()});
                }
            }
        contact_term_start.push_back(contact_terms.size());
      }
  }

  void
  CondensedStep::solve(const std::vector<ContactPiece> &pieces,
                       std::vector<double>             &p)
  {
    const unsigned int n_u = system.n_displacement_dofs;
    // Constraints d . u = value for prescribed and pressed rows: the dof
    // with the largest |d_k| is expressed by the others of its node. Every
    // process knows those of its relevant dofs (owned and ghost).
    AffineConstraints<double> constraints(partition.relevant);
    auto constrain = [&](const EquilibriumRow &row, const double value) {
      unsigned int k_max = 0;
      for (unsigned int k = 1; k < row.combination.size(); ++k)
        if (std::abs(row.direction_component(k)) >
            std::abs(row.direction_component(k_max)))
          k_max = k;
      const auto   dof = row.combination[k_max].first;
      const double d   = row.direction_component(k_max);
      constraints.add_line(dof);
      for (unsigned int k = 0; k < row.combination.size(); ++k)
        if (k != k_max && row.direction_component(k) != 0)
          constraints.add_entry(dof,
                                row.combination[k].first,
                                -row.direction_component(k) / d);
      constraints.set_inhomogeneity(dof, value / d);
    };
    // Several held rows at one node (a node in a corner between obstacles,
    // eq. 11): d_r . u = value_r jointly, by Gauss-Jordan elimination with
    // the largest pivot of each row, so that every constrained dof is
    // expressed by the free ones only.
    auto constrain_jointly =
      [&](const std::vector<std::pair<const EquilibriumRow *, double>> &rows) {
        const auto        &dofs = rows.front().first->combination;
        const unsigned int m = rows.size(), n = dofs.size();
        FullMatrix<double> D(m, n);
        Vector<double>     b(m);
        for (unsigned int r = 0; r < m; ++r)
          {
            for (unsigned int k = 0; k < n; ++k)
              D(r, k) = rows[r].first->direction_component(k);
            b[r] = rows[r].second;
          }
        std::vector<unsigned int> pivot(m);
        std::vector<bool>         is_pivot(n, false);
        for (unsigned int r = 0; r < m; ++r)
          {
            unsigned int c = n;
            for (unsigned int k = 0; k < n; ++k)
              if (!is_pivot[k] &&
                  (c == n || std::abs(D(r, k)) > std::abs(D(r, c))))
                c = k;
            if (c == n || std::abs(D(r, c)) < 1e-10)
              throw InputError(
                "the constraints held at " +
                system.describe_node(rows[r].first->node) +
                " are linearly dependent (obstacles with parallel normals?).");
            pivot[r]           = c;
            is_pivot[c]        = true;
            const double scale = D(r, c);
            for (unsigned int k = 0; k < n; ++k)
              D(r, k) /= scale;
            b[r] /= scale;
            for (unsigned int s = 0; s < m; ++s)
              if (s != r && D(s, c) != 0)
                {
                  const double factor = D(s, c);
                  for (unsigned int k = 0; k < n; ++k)
                    D(s, k) -= factor * D(r, k);
                  b[s] -= factor * b[r];
                }
          }
        for (unsigned int r = 0; r < m; ++r)
          {
            constraints.add_line(dofs[pivot[r]].first);
            for (unsigned int k = 0; k < n; ++k)
              if (!is_pivot[k] && D(r, k) != 0)
                constraints.add_entry(dofs[pivot[r]].first,
                                      dofs[k].first,
                                      -D(r, k));
            constraints.set_inhomogeneity(dofs[pivot[r]].first, b[r]);
          }
      };
    // The dofs of a node all belong to the same process.
    auto relevant = [&](const EquilibriumRow &row) {
      return partition.relevant.is_element(row.combination.front().first);
    };
    // Held rows per node: the prescribed ones and the held Q rows; springs.
    std::map<unsigned int,
             std::vector<std::pair<const EquilibriumRow *, double>>>
                                         held;
    std::map<unsigned int, unsigned int> held_q_rows;
    std::vector<std::pair<const EquilibriumRow *, const ContactPiece *>>
      springs;
    for (const unsigned int r : system.prescribed_rows)
      if (relevant(system.rows[r]))
        held[system.rows[r].node].emplace_back(&system.rows[r],
                                               system.rows[r].value);
    for (const unsigned int i : row_ownership.relevant())
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        if (!pieces[i].spring)
          {
            held[row.node].emplace_back(&row, row.value + pieces[i].offset);
            ++held_q_rows[row.node];
          }
        else if (row_ownership.is_owned(i))
          springs.emplace_back(&row, &pieces[i]);
      }
    // A process sees only its relevant nodes: an error found at one of
    // them must stop every process, or the others would wait in the
    // assembly's communication.
    std::string error;
    try
      {
        for (const auto &[node, rows] : held)
          if (held_q_rows[node] > 1)
            constrain_jointly(rows);
          else
            for (const auto &[row, value] : rows)
              constrain(*row, value);
      }
    catch (const InputError &e)
      {
        error = e.what();
      }
    if (partition.distributed())
      for (const auto &e :
           Utilities::MPI::all_gather(partition.communicator, error))
        if (error.empty())
          error = e;
    if (!error.empty())
      throw InputError(error);
    constraints.close();

    // A spring 1/compliance along d anchored at g + offset: the node matrix
    // k d d^T and the force k (g + offset) d.
    auto spring = [](const EquilibriumRow &row,
                     const ContactPiece   &piece,
                     FullMatrix<double>   &matrix,
                     Vector<double>       &force) {
      const unsigned int n   = row.combination.size();
      const double       k_s = 1. / piece.compliance;
      matrix.reinit(n, n);
      force.reinit(n);
      for (unsigned int a = 0; a < n; ++a)
        {
          force[a] =
            row.direction_component(a) * k_s * (row.value + piece.offset);
          for (unsigned int b = 0; b < n; ++b)
            matrix(a, b) =
              k_s * row.direction_component(a) * row.direction_component(b);
        }
    };
    FullMatrix<double>                   spring_matrix;
    Vector<double>                       spring_force;
    std::vector<types::global_dof_index> node_dofs;

    // What K and the springs depend on, beyond the fixed part: per Q row
    // held (-1) or the spring's compliance, and its direction (rows that
    // follow the configuration move it, and a matrix of the old directions
    // would be off by as much). The held values and the spring anchors
    // (g + offset) enter the right-hand side only.
    // Each process keys the rows it sees; whether the matrix stays is
    // agreed on by all (its assembly is collective).
    std::vector<double> key;
    key.reserve(row_ownership.relevant().size() * (1 + system.dim));
    for (const unsigned int i : row_ownership.relevant())
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        key.push_back(pieces[i].spring ? pieces[i].compliance : -1.);
        for (unsigned int k = 0; k < row.combination.size(); ++k)
          key.push_back(row.direction_component(k));
      }

    ++statistics.solves;
    if (distributed)
      {
        Timer timer;
        auto &A   = distributed->matrix;
        auto &rhs = distributed->rhs;
        auto &d   = *distributed;
        rhs       = 0;
        // The same held rows and springs as the matrix has (a multiplier
        // update with no branch or penalty changed): the right-hand side
        // only, the constraints' inhomogeneities eliminated with the kept
        // cells' and springs' matrices as the assembly with the matrix does;
        // and the AMG hierarchy stays valid.
        const bool same_matrix =
          row_ownership.all(d.assembled && d.matrix_key == key);
        if (!same_matrix)
          {
            // The rows the last step changed go back to the fixed part of K.
            d.set_row_values(d.fixed_values);
            d.direct_solver.reset();
            // A new matrix needs a new hierarchy, unless the settings keep
            // one across steps (solve_cg_amg).
            if (!settings.reuses_preconditioner(system.dim))
              d.built = false;
          }
        auto distribute =
          [&](const FullMatrix<double>                   &M,
              const Vector<double>                       &f,
              const std::vector<types::global_dof_index> &dofs) {
            if (same_matrix)
              constraints.distribute_local_to_global(f, dofs, rhs, M);
            else
              constraints.distribute_local_to_global(M, f, dofs, A, rhs);
          };
        // Loads enter per dof below; the cells at Q and H rows bring
        // stiffness only.
        const unsigned int n_per_cell = d.dofs_per_cell;
        const std::size_t  n_owned_cells =
          (n_per_cell == 0) ? 0 : d.cell_dofs.size() / n_per_cell;
        Vector<double>                       no_cell_force(n_per_cell);
        FullMatrix<double>                   Kc(n_per_cell, n_per_cell);
        std::vector<types::global_dof_index> du(n_per_cell);
        for (std::size_t k = 0; k < n_owned_cells; ++k)
          {
            const std::size_t first = std::size_t(k) * n_per_cell;
            std::copy(d.cell_dofs.begin() + first,
                      d.cell_dofs.begin() + first + n_per_cell,
                      du.begin());
            const double *values = d.cell_stiffness.data() + first * n_per_cell;
            for (unsigned int i = 0; i < n_per_cell; ++i)
              for (unsigned int j = 0; j < n_per_cell; ++j)
                Kc(i, j) = values[i * n_per_cell + j];
            no_cell_force = 0;
            distribute(Kc, no_cell_force, du);
          }
        for (const auto &[row, piece] : springs)
          {
            spring(*row, *piece, spring_matrix, spring_force);
            node_dofs.clear();
            for (const auto &[dof, c] : row->combination)
              node_dofs.push_back(dof);
            distribute(spring_matrix, spring_force, node_dofs);
          }
        add_strain_loads([&](const std::vector<types::global_dof_index> &dofs,
                             const Vector<double> &values) {
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
        if (!same_matrix)
          {
            A.compress(VectorOperation::add);
            d.matrix_key = key;
            d.assembled  = true;
          }
        rhs.compress(VectorOperation::add);
        statistics.setup_seconds += timer.wall_time();

        if (!settings.warm_start)
          distributed->u = 0;
        else
          {
            // The last solution carries the held values in its constrained
            // entries (distribute), where this system's decoupled rows ask
            // for zero: left there, they would start CG with a residual as
            // large as their diagonal forces (Hertz refinement 8: 0.67 of
            // the right-hand side instead of 1e-8).
            auto &u_start = distributed->u;
            for (const auto &line : constraints.get_lines())
              if (u_start.in_local_range(line.index))
                u_start(line.index) = 0;
            u_start.compress(VectorOperation::insert);
          }
        if (solver == LinearSolverKind::cg_amg)
          solve_cg_amg();
        else
          solve_direct_distributed();
        constraints.distribute(distributed->u);
        // The owned dofs, and the ghosts from their owners; or every dof on
        // every process (see ghosted_u).
        if (ghosted_u)
          u.reinit(partition.owned, partition.relevant, partition.communicator);
        else
          u.reinit(n_u);
        for (const auto i : partition.owned)
          u(i) = distributed->u[i];
        if (ghosted_u)
          u.update_ghost_values();
        else if (partition.distributed())
          {
            const ArrayView<const double> values(u.begin(), u.size());
            const ArrayView<double>       sums(u.begin(), u.size());
            Utilities::MPI::sum(values, partition.communicator, sums);
          }
      }
    else
      {
        // K and the springs, factorised again only when a held row or a
        // spring's compliance changed (DirectFactor).
        Timer      timer;
        double     factor_seconds = 0;
        const bool refactorise    = !direct_factor || direct_factor->key != key;
        if (refactorise)
          {
            direct_factor.reset(); // free the old factors first
            direct_factor      = std::make_unique<DirectFactor>();
            direct_factor->key = key;
            SparseMatrix<double> A(sparsity);
            A.copy_from(K);
            for (const auto &[row, piece] : springs)
              {
                spring(*row, *piece, spring_matrix, spring_force);
                for (unsigned int a = 0; a < row->combination.size(); ++a)
                  for (unsigned int b = 0; b < row->combination.size(); ++b)
                    A.add(row->combination[a].first,
                          row->combination[b].first,
                          spring_matrix(a, b));
              }
            constraints.condense(A);
            try
              {
                direct_factor->factor.initialize(A);
              }
            catch (const std::exception &)
              {
                direct_factor.reset();
                throw InputError(singular_stiffness_message);
              }
            ++statistics.preconditioner_setups;
            factor_seconds = timer.wall_time();
            statistics.setup_seconds += factor_seconds;
          }
        // u = u_c + v: u_c carries the inhomogeneities (the held values),
        // v solves the homogeneously constrained system with the right-hand
        // side f + spring forces - (K + springs) u_c, condensed like the
        // matrix.
        Vector<double> u_c(n_u), r(n_u);
        constraints.distribute(u_c);
        K.residual(r,
                   u_c,
                   Vector<double>(system.load.begin(), system.load.end()));
        add_strain_loads([&](const std::vector<types::global_dof_index> &dofs,
                             const Vector<double> &values) {
          for (unsigned int i = 0; i < dofs.size(); ++i)
            r[dofs[i]] += values[i];
        });
        for (const auto &[row, piece] : springs)
          {
            spring(*row, *piece, spring_matrix, spring_force);
            for (unsigned int a = 0; a < row->combination.size(); ++a)
              {
                double spring_times_u_c = 0;
                for (unsigned int b = 0; b < row->combination.size(); ++b)
                  spring_times_u_c +=
                    spring_matrix(a, b) * u_c[row->combination[b].first];
                r[row->combination[a].first] +=
                  spring_force[a] - spring_times_u_c;
              }
          }
        for (const auto &line : constraints.get_lines())
          for (const auto &[dof, coefficient] : line.entries)
            r[dof] += coefficient * r[line.index];
        for (const auto &line : constraints.get_lines())
          r[line.index] = 0;
        Vector<double> x(n_u);
        direct_factor->factor.vmult(x, r);
        constraints.distribute(x);
        u.reinit(n_u);
        std::copy(x.begin(), x.end(), u.begin());
        statistics.solve_seconds += timer.wall_time() - factor_seconds;
      }

    for (unsigned int k = 0; k < recovery_cells.size(); ++k)
      {
        const auto &du = system.cell_displacement_dofs[recovery_cells[k]];
        double     *s  = recovered_stress.data() + recovered_offset[k];
        const auto  n  = recovered_offset[k + 1] - recovered_offset[k];
        for (unsigned int i = 0; i < n; ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < du.size(); ++j)
              sum += recovery[k](i, j) * u[du[j]];
            s[i] = sum;
          }
        if (!recovered_shift.empty())
          for (unsigned int i = 0; i < n; ++i)
            s[i] -= recovered_shift[recovered_offset[k] + i];
      }
    // p of each row by the owner of its node, the only process that has
    // every cell around it on a distributed mesh; the rows of ghost nodes
    // from their owners.
    p.assign(system.contact_rows.size(), 0.);
    for (const unsigned int i : row_ownership.owned())
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        double                sum = 0;
        for (std::size_t t = contact_term_start[i];
             t < contact_term_start[i + 1];
             ++t)
          {
            const StressTerm &term = contact_terms[t];
            sum += row.combination[term.k].second * term.b *
                   recovered_stress[term.position];
          }
        p[i] = sum - system.row_load(row);
      }
    row_ownership.import_ghosts(p);
  }

  void
  CondensedStep::solve_direct_distributed()
  {
    Timer  timer;
    double factor_seconds = 0;
    auto  &d              = *distributed;
    try
      {
        if (!d.direct_solver)
          {
            d.direct_control = std::make_unique<SolverControl>(1, 0);
            d.direct_solver  = std::make_unique<TrilinosWrappers::SolverDirect>(
              *d.direct_control,
              TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                             "Amesos_Mumps"));
            d.direct_solver->initialize(d.matrix);
            ++statistics.preconditioner_setups;
            factor_seconds = timer.wall_time();
            statistics.setup_seconds += factor_seconds;
          }
        d.direct_solver->solve(d.u, d.rhs);
      }
    catch (const std::exception &)
      {
        d.direct_solver.reset();
        throw InputError(singular_stiffness_message);
      }
    // MUMPS returns some vector for a singular matrix (a floating body, a
    // mechanism) without a word: an inconsistent system shows in the
    // residual, which UMFPACK and CG would have refused.
    TrilinosWrappers::MPI::Vector residual(distributed->rhs);
    distributed->matrix.vmult(residual, distributed->u);
    residual -= distributed->rhs;
    const double scale = distributed->rhs.l2_norm();
    if (!(residual.l2_norm() <= 1e-8 * std::max(scale, 1e-300)))
      throw InputError(singular_stiffness_message);
    statistics.solve_seconds += timer.wall_time() - factor_seconds;
  }

  void
  CondensedStep::solve_cg_amg()
  {
    Timer timer;
    // The AMG set-ups' share, counted as set-up and not as solve.
    double setup_seconds = 0;

    auto       &d     = *distributed;
    const auto &rhs   = d.rhs;
    const bool  reuse = settings.reuses_preconditioner(system.dim);
    auto        setup = [&]() {
      Timer setup_timer;
      d.preconditioner.clear();
      // ML keeps a pointer to the matrix: a hierarchy that outlives the
      // step keeps the values of the rows the steps change.
      if (reuse)
        d.setup_values = d.row_values();
      const TrilinosWrappers::SparseMatrix &M = d.matrix;
      // Smoothed aggregation for an elliptic operator; the near null space
      // is the rigid-body modes (ML's pre-computed null space), since the
      // translations alone (deal.II 9.4's constant modes) coarsen bending
      // poorly.
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = settings.smoother_sweeps;
      data.aggregation_threshold = settings.aggregation_threshold;
      Teuchos::ParameterList              list;
      std::unique_ptr<Epetra_MultiVector> unused;
      data.set_parameters(list, unused, M);
      const unsigned int dim     = system.dim;
      const unsigned int n_modes = (dim == 2) ? 3 : 6;
      const auto        &map     = M.trilinos_matrix().DomainMap();
      d.modes = std::make_unique<Epetra_MultiVector>(map, n_modes);
      for (int k = 0; k < map.NumMyElements(); ++k)
        {
          const auto         i = TrilinosWrappers::global_index(map, k);
          const unsigned int c = system.dof_component(i);
          const auto        &x = system.node_coordinates[system.dof_node(i)];
          for (unsigned int m = 0; m < n_modes; ++m)
            (*d.modes)[m][k] = 0;
          (*d.modes)[c][k] = 1; // translations
          // Rotations about the axes: (-y, x, 0), (0, -z, y), (z, 0, -x).
          if (dim == 2)
            (*d.modes)[2][k] = (c == 0) ? -x[1] : x[0];
          else
            {
              (*d.modes)[3][k] = (c == 0) ? -x[1] : (c == 1) ? x[0] : 0.;
              (*d.modes)[4][k] = (c == 1) ? -x[2] : (c == 2) ? x[1] : 0.;
              (*d.modes)[5][k] = (c == 2) ? -x[0] : (c == 0) ? x[2] : 0.;
            }
        }
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", static_cast<int>(n_modes));
      list.set("null space: vectors", d.modes->Values());
      list.set("null space: add default vectors", false);
      statistics.aggregation =
        settings.aggregates_by_coordinates() ? "coordinates" : "matrix";
      if (settings.aggregates_by_coordinates())
        {
          // ML's auxiliary aggregation reads one coordinate per node, the
          // nodes' dofs numbered together (dim n + d, on one process).
          for (auto &c : d.node_xyz)
            c.clear();
          for (int k = 0; k < map.NumMyElements(); ++k)
            {
              const auto i = TrilinosWrappers::global_index(map, k);
              AssertThrow(system.dof_component(i) == k % dim,
                          ExcMessage("coordinate aggregation needs each "
                                            "node's dofs together on one process"));
              if (k % dim == 0)
                for (unsigned int c = 0; c < dim; ++c)
                  d.node_xyz[c].push_back(
                    system.node_coordinates[system.dof_node(i)][c]);
            }
          const char *axis[3] = {"x-coordinates",
                                 "y-coordinates",
                                 "z-coordinates"};
          for (unsigned int c = 0; c < dim; ++c)
            list.set(axis[c], d.node_xyz[c].data());
          list.set("PDE equations", static_cast<int>(dim));
          list.set("aggregation: aux: enable", true);
          list.set("aggregation: aux: threshold",
                   settings.coordinate_threshold);
        }
      d.preconditioner.initialize(M, list);
      d.built = true;
      ++statistics.preconditioner_setups;
      setup_seconds += setup_timer.wall_time();
    };
    bool fresh = false;
    if (!d.built)
      {
        setup();
        fresh = true;
      }
    // CG stops at cg_tolerance of the right-hand side, as from a zero start;
    // a warm start whose residual is already near that (a multiplier update
    // that moves a few rows) must still resolve its change, or p would not
    // move and the multipliers would stall (the bridge with stops took 16
    // updates instead of 6): then it stops at Warm start reduction of its
    // initial residual, but not below 1e-15 of the right-hand side.
    const double rhs_norm  = rhs.l2_norm();
    double       tolerance = cg_tolerance * rhs_norm;
    if (settings.warm_start)
      {
        TrilinosWrappers::MPI::Vector r0(rhs);
        d.matrix.vmult(r0, d.u);
        r0.sadd(-1., rhs);
        tolerance =
          std::max(std::min(tolerance,
                            settings.warm_start_reduction * r0.l2_norm()),
                   std::min(tolerance, 1e-15 * rhs_norm));
      }
    auto run_cg = [&]() {
      SolverControl control(settings.max_iterations, tolerance, false, false);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      try
        {
          if (reuse)
            cg.solve(d.matrix, d.u, rhs, Distributed::AtSetupValues{d});
          else
            cg.solve(d.matrix, d.u, rhs, d.preconditioner);
        }
      catch (const SolverControl::NoConvergence &)
        {
          statistics.iterations += control.last_step();
          return std::make_pair(false, control.last_step());
        }
      statistics.iterations += control.last_step();
      return std::make_pair(true, control.last_step());
    };
    auto [converged, steps] = run_cg();
    if (!converged && !fresh)
      {
        // A hierarchy from an earlier Newton step no longer serves: rebuild.
        setup();
        fresh                      = true;
        std::tie(converged, steps) = run_cg();
      }
    if (!converged)
      {
        std::ostringstream what;
        what << "Condensed path: CG with AMG did not reach ";
        if (statistics.tightenings > 0)
          what << "the tolerance " << cg_tolerance
               << " (Linear solver/Tolerance, tightened after an inner "
                  "Newton cycle)";
        else
          what << "Linear solver/Tolerance";
        what << " in Linear solver/Maximum iterations = "
             << settings.max_iterations
             << " iterations. Raise the limit, loosen the tolerance, or take "
                "Linear solver/Solver = direct.";
        throw NotConvergedError(what.str());
      }
    if (statistics.solves == 1)
      statistics.first_solve_iterations = statistics.iterations;
    if (fresh)
      d.iterations_after_setup = steps;
    else if (steps > 2 * d.iterations_after_setup + 5)
      d.built = false; // rebuild before the next solve
    statistics.setup_seconds += setup_seconds;
    statistics.solve_seconds += timer.wall_time() - setup_seconds;
  }

  void
  CondensedStep::stresses(FieldVector &stress) const
  {
    // Every process recovers its own cells, the stored ones from their kept
    // F_c^{-1} B_c^T (already done by the last solve), the others (a lean
    // system) from recomputed blocks, in the same operations. The stress
    // dofs of a cell are its own: on a distributed mesh the owner of the cell
    // owns them, and its ghost cells' entries come from their owners; a
    // complete vector (a serial mesh under MPI) is the sum over the
    // processes.
    AssertDimension(stress.size(), system.n_stress_dofs);
    stress = 0;
    for (unsigned int k = 0; k < recovery_cells.size(); ++k)
      if (partition.owned_cell[recovery_cells[k]])
        {
          const auto &ds = system.cell_stress_dofs[recovery_cells[k]];
          for (unsigned int j = 0; j < ds.size(); ++j)
            stress(ds[j]) = recovered_stress[recovered_offset[k] + j];
        }
    if (!recovery_complete)
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
              stress(ds[i]) = s_c[i];
          });
      }
    if (!is_complete(stress))
      stress.update_ghost_values();
    else if (partition.distributed())
      {
        const ArrayView<const double> values(stress.begin(), stress.size());
        const ArrayView<double>       sums(stress.begin(), stress.size());
        Utilities::MPI::sum(values, partition.communicator, sums);
      }
  }

  void
  NewtonStepPath::set_start(const FieldVector &)
  {}

  void
  CondensedStep::set_start(const FieldVector &u_start)
  {
    AssertDimension(u_start.size(), system.n_displacement_dofs);
    if (!distributed || solver != LinearSolverKind::cg_amg ||
        !settings.warm_start)
      return;
    for (const auto i : partition.owned)
      distributed->u[i] = u_start(i);
    distributed->u.compress(VectorOperation::insert);
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
        const ArrayView<const double> values(displacement.begin(),
                                             displacement.size());
        const ArrayView<double> sums(displacement.begin(), displacement.size());
        Utilities::MPI::sum(values, partition.communicator, sums);
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

  void
  NewtonStepPath::rows_changed()
  {}

  void
  NullSpaceStep::rows_changed()
  {
    throw InputError(
      "the null-space path cannot follow constraint rows that change during "
      "the solve (curved obstacles updated between multiplier updates need "
      "Equilibrium reduction/Path = condensed).");
  }

  bool
  NewtonStepPath::tighten_linear_solver()
  {
    return false;
  }

  bool
  CondensedStep::tighten_linear_solver()
  {
    // Below 1e-15 of the right-hand side CG stagnates in double precision.
    constexpr double floor = 1e-15;
    if (solver != LinearSolverKind::cg_amg || cg_tolerance <= floor)
      return false;
    cg_tolerance         = std::max(floor, 1e-2 * cg_tolerance);
    statistics.tolerance = cg_tolerance;
    ++statistics.tightenings;
    return true;
  }

  void
  NewtonStepPath::contact_displacements(std::vector<double> &) const
  {
    throw InputError(
      "this Newton-step path cannot give the normal displacement of a "
      "contact node without a spring (the displacement-based augmented "
      "Lagrangian needs Equilibrium reduction/Path = condensed).");
  }
} // namespace hrcontact
