#ifndef hrcontact_newton_step_h
#define hrcontact_newton_step_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  class CellStiffness;

  /**
   * One exact Newton step of the augmented Lagrangian (doc/method.md, "Two
   * exact Newton-step paths"): the maximiser of the quadratic piece of eq. 44
   * that the constraint laws select, one ContactPiece per Q row: a held row
   * keeps w_n = g + offset, a spring row w_n - g = offset - compliance p. The
   * two implementations give the same iterates in exact arithmetic.
   */
  class NewtonStepPath
  {
  public:
    virtual ~NewtonStepPath() = default;

    /**
     * Solve the piece; return p = Q s - q for the Q rows this process sees
     * (row_partition().relevant(): every row on one process). Only the
     * pieces of those rows are read.
     */
    virtual void
    solve(const std::vector<ContactPiece> &pieces, std::vector<double> &p) = 0;

    /** Which Q rows this process owns and sees (every row unless the path
     * is distributed). */
    const ContactRowPartition &
    row_partition() const
    {
      return row_ownership;
    }

    /**
     * The unilateral shorthand: released rows are springs of compliance
     * alpha_i anchored at g_i + mu_i, the others are held at w_n = g.
     */
    void
    solve(const std::vector<bool>   &released,
          const std::vector<double> &mu,
          const std::vector<double> &alpha,
          std::vector<double>       &p);

    /**
     * Stresses of the last solve into s, sized by reinit_field(): on a
     * distributed mesh each process fills its own cells' and its ghost
     * cells' entries, without a global vector; otherwise s is complete.
     */
    virtual void
    stresses(FieldVector &s) const = 0;

    /**
     * Displacements to start the next solve's iterations from (nested
     * iteration: the coarser level's, prolongated), indexed as the
     * displacement dofs; distributed or complete as reinit_field makes it.
     * Exact solvers have no use for it and ignore it.
     */
    virtual void
    set_start(const FieldVector &u_start);

    /**
     * Nodal displacements of the last solve, given the normal displacements
     * of the Q rows (g + mu after the last multiplier update), into u sized
     * by the caller: distributed (reinit_field) or complete (reinit(n), then
     * gathered on every process).
     */
    virtual void
    displacements(const std::vector<double> &contact_w,
                  FieldVector               &u) const = 0;

    /**
     * w_n = d . u of the Q rows this process sees after the last solve,
     * needed by the displacement AL for rows without a spring. The null-space
     * path knows u only through the rows' w_n, so it cannot (and throws
     * InputError).
     */
    virtual void
    contact_displacements(std::vector<double> &w) const;

    /**
     * A RowRelinearisation rewrote the directions and gaps of some Q rows
     * between multiplier updates: the next solve must use them. The
     * condensed path reads the rows at every solve and only drops a kept
     * factorisation; the null-space path built its reduction from the initial
     * rows and cannot follow (InputError).
     */
    virtual void
    rows_changed();

    /**
     * The cells' F_c in the system changed (a material whose compliance
     * depends on its state, MaterialLaw; see HRAssembler::refresh_flexibility):
     * rebuild what depends on F before the next solve.
     */
    virtual void
    flexibility_changed() = 0;

    /**
     * The inner Newton iteration came back to a released set it had solved
     * (AugmentedLagrangianSolver): with an iterative linear solver, the
     * usual cause is that its residual no longer fixes p = Q s - q to the
     * digits the constraint laws compare (measured on Hertz refinement 10,
     * 6.3M dofs, at Tolerance 1e-12). Tighten it for the remaining solves;
     * false when the path solves exactly (dense, direct) or CG is at its
     * floor already.
     */
    virtual bool
    tighten_linear_solver();

    /** Linear solver counters (zero for the dense path). */
    LinearSolverStatistics statistics;

  protected:
    /** Set by the constructor of a distributed path. */
    ContactRowPartition row_ownership;
  };

  /**
   * The paper's path (section 4.2-4.3) on the reduced unknowns s0:
   * (M0 + sum_released alpha_i q_i q_i^T) s0 = b0 + sum_released q_i (mu_i -
   * alpha_i a_i), q_i the rows of Q R. M0's Cholesky factor comes from the
   * reduction; the released rows are a low-rank update solved by the
   * Woodbury identity with Z = M0^{-1} (QR)^T and S = QR Z, computed once.
   */
  class NullSpaceStep : public NewtonStepPath
  {
  public:
    /** The reduction is updated by flexibility_changed(). */
    explicit NullSpaceStep(EquilibriumReduction &reduction);

    using NewtonStepPath::solve;
    void
    solve(const std::vector<ContactPiece> &pieces,
          std::vector<double>             &p) override;
    /** s must be complete: the null-space path runs on a serial mesh. */
    void
    stresses(FieldVector &s) const override;
    void
    displacements(const std::vector<double> &contact_w,
                  FieldVector               &u) const override;
    void
    rows_changed() override;
    /** M0 again (EquilibriumReduction::flexibility_changed), then Z, S. */
    void
    flexibility_changed() override;

  private:
    /** Z and S from the reduction. */
    void
    prepare();

    EquilibriumReduction      &reduction;
    std::vector<double>        Z;
    dealii::FullMatrix<double> S;
    dealii::Vector<double>     s0;
  };

  /**
   * The condensed path (doc/method.md): the stresses are eliminated
   * cell by cell (F is block diagonal), K = B F^{-1} B^T is a sparse SPD
   * displacement-like matrix; prescribed and pressed rows become
   * AffineConstraints (d . u = value), released rows add springs 1/alpha_i
   * along their direction with the anchor g_i + mu_i; the solve gives u, then
   * s = F^{-1} B^T u per cell. Memory and work grow about linearly with the
   * mesh, unlike the dense null-space path.
   *
   * Two back ends: the serial direct one condenses a deal.II matrix and
   * factorises it with UMFPACK; the Trilinos one assembles K cell by cell
   * into a distributed Trilinos matrix over the given DofPartition (every
   * cell it owns, constraints applied while assembling, as in step-40) and
   * solves it with CG + ML AMG, or with MUMPS (through Amesos) when Solver =
   * direct runs on several processes. Each process then holds u on its
   * relevant dofs (gathered whole only on a serial mesh under MPI, see
   * ghosted_u), recovers the stresses of its cells, and computes p for the
   * rows of the nodes it owns; the rows of its ghost nodes get theirs from
   * their owners (ContactRowPartition).
   */
  class CondensedStep : public NewtonStepPath
  {
  public:
    /**
     * With `stiffness`, K is assembled from that bilinear form instead of B
     * F^-1 B^T (the Q1 floor of the benchmarks); the path then gives
     * displacements only (no stresses, and p is meaningless).
     */
    CondensedStep(const EquilibriumSystem    &system,
                  const LinearSolverSettings &settings = LinearSolverSettings(),
                  const DofPartition         *partition = nullptr,
                  const CellStiffness        *stiffness = nullptr);
    ~CondensedStep() override;

    using NewtonStepPath::solve;
    void
    solve(const std::vector<ContactPiece> &pieces,
          std::vector<double>             &p) override;
    void
    stresses(FieldVector &s) const override;
    /** CG starts from it (its constrained entries zeroed, as any warm
     * start's); MUMPS and UMFPACK ignore it. */
    void
    set_start(const FieldVector &u_start) override;
    void
    displacements(const std::vector<double> &contact_w,
                  FieldVector               &u) const override;
    void
    contact_displacements(std::vector<double> &w) const override;
    /** K and the stress recovery again from the system's F_c. */
    void
    flexibility_changed() override;
    /** The rows' directions moved: a kept factorisation no longer fits. */
    void
    rows_changed() override;
    /** CG only: its tolerance x 1e-2, down to 1e-15. */
    bool
    tighten_linear_solver() override;

  private:
    /** K_c = B_c F_c^-1 B_c^T of the owned cells into K (or the Trilinos
     * back end's cell stiffness), F_c^-1 B_c^T of the stored cells. */
    void
    assemble();
    /** recovered_offset and the terms of p from the recovery cells. */
    void
    index_recovered_stresses();
    /** Each owned cell's B_c F_c^-1 d_c with its dofs (strain_load_*). */
    void
    add_strain_loads(const std::function<
                     void(const std::vector<dealii::types::global_dof_index> &,
                          const dealii::Vector<double> &)> &add) const;
    /** Solve the assembled Trilinos system by CG + AMG (warm start in u). */
    void
    solve_cg_amg();
    /** Solve the assembled Trilinos system by MUMPS through Amesos. */
    void
    solve_direct_distributed();

    const EquilibriumSystem   &system;
    const LinearSolverSettings settings;
    /** Another bilinear form for K, or null (B F^-1 B^T). */
    const CellStiffness *stiffness;
    const DofPartition   partition;
    LinearSolverKind     solver = LinearSolverKind::direct;
    /** CG's relative tolerance now (tighten_linear_solver). */
    double cg_tolerance;
    /** Serial direct back end: the pattern and K itself. */
    dealii::SparsityPattern      sparsity;
    dealii::SparseMatrix<double> K;
    /**
     * The cells whose stresses every Newton step needs (the system's stored
     * cells: those of the Q and H rows, or all), and their F_c^{-1} B_c^T
     * (stress dofs x displacement dofs).
     */
    std::vector<unsigned int>               recovery_cells;
    std::vector<dealii::FullMatrix<double>> recovery;
    /** Whether recovery_cells holds every cell. */
    bool recovery_complete = true;
    /**
     * u of the last solve: on a distributed mesh with lean storage the owned
     * and ghost (relevant) dofs only, which is all that the recovery cells
     * and the rows of owned nodes read; otherwise complete, gathered after
     * every solve (a serial mesh under MPI, whose owned dofs are not a
     * contiguous range).
     */
    FieldVector u;
    /** Whether u holds only the relevant dofs (above). */
    bool ghosted_u = false;
    /**
     * The stresses of the recovery cells only, cell after cell (cell k's
     * from recovered_offset[k]): on a lean system the cells at Q and H rows,
     * a surface, instead of a vector of every stress dof of the mesh on
     * every process (75 MB at Hertz refinement 9, 98 MB on the 3D block at
     * 807k dofs).
     */
    std::vector<double>      recovered_stress;
    std::vector<std::size_t> recovered_offset;
    /**
     * A material Newton step (EquilibriumSystem::cell_strain_term): per
     * recovery cell F_c^{-1} d_c, laid out as recovered_stress and taken
     * from it (s_c = F_c^{-1} (B_c^T u - d_c)), and per owned cell the load
     * B_c F_c^{-1} d_c and its dofs, cell after cell. Empty for a linear
     * law.
     */
    std::vector<double>                          recovered_shift;
    std::vector<dealii::types::global_dof_index> strain_load_dofs;
    std::vector<double>                          strain_load_values;
    std::size_t                                  strain_load_cell_size = 0;
    /**
     * p = Q s - q without a global stress vector: for each Q row this
     * process owns, its terms (the index k into the row's combination, the
     * position in recovered_stress, the entry of B) in the order of
     * EquilibriumSystem::row_times, so that the sums are the same to the
     * last bit; the row's coefficients are read at each step (rows that
     * follow the configuration change them). Rows contact_term_start[i] to
     * contact_term_start[i + 1].
     */
    struct StressTerm
    {
      unsigned int k;
      std::size_t  position;
      double       b;
    };
    std::vector<StressTerm>  contact_terms;
    std::vector<std::size_t> contact_term_start;
    /** Trilinos back end (kept between Newton steps). */
    struct Distributed;
    std::unique_ptr<Distributed> distributed;
    /**
     * Serial direct back end: the factorisation of the last condensed K
     * plus springs, kept while the held rows, the springs' compliances and
     * the rows' directions stay the same.
     * A multiplier update that changes no branch only moves the anchors
     * (g + offset): the right-hand side, not K, so the next step costs a
     * forward and back substitution instead of a factorisation.
     */
    struct DirectFactor;
    std::unique_ptr<DirectFactor> direct_factor;
  };
} // namespace hrcontact

#endif
