#ifndef hrcontact_condensed_step_h
#define hrcontact_condensed_step_h

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/condensed/linear_back_end.h>
#include <hrcontact/solvers/condensed/strain_loads.h>
#include <hrcontact/solvers/condensed/stress_recovery.h>
#include <hrcontact/solvers/linear_solver_settings.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <memory>
#include <vector>

namespace hrcontact
{
  class CellStiffness;

  /**
   * The condensed path (doc/method.md): the stresses are eliminated
   * cell by cell (F is block diagonal), K = B F^{-1} B^T is a sparse SPD
   * displacement-like matrix; prescribed and pressed rows become
   * AffineConstraints (d . u = value, StepRows), released rows add springs
   * 1/alpha_i along their direction with the anchor g_i + mu_i; the solve
   * gives u (a CondensedBackEnd), then s = F^{-1} B^T u per cell
   * (StressRecovery). Memory and work grow about linearly with the mesh,
   * unlike the dense null-space path.
   *
   * Each process holds u on its relevant dofs (gathered whole only on a
   * serial mesh under MPI, see ghosted_u), recovers the stresses of its
   * cells, and computes p for the rows of the nodes it owns; the rows of its
   * ghost nodes get theirs from their owners (ContactRowPartition).
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
    bool
    displacements_are_unknowns() const override
    {
      return true;
    }
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
    /** K_c = B_c F_c^-1 B_c^T of the owned cells into the back end,
     * F_c^-1 B_c^T of the stored cells into the recovery. */
    void
    assemble();
    /**
     * One pass over the cells this process owns and those whose stresses
     * every step needs, from the stored blocks or recomputed (a lean
     * system): each owned cell's K_c to @p add_owned (and its strain load
     * kept), each stored cell's F_c^{-1} B_c^T to the recovery.
     */
    void
    condense_cells(const CellStiffnessSink &add_owned);
    /** The couplings of the owned cells and of the Q rows that tie several
     * nodes, from their dofs alone (no K_c buffered for the pattern). */
    void
    add_couplings(dealii::DynamicSparsityPattern &dsp) const;

    const EquilibriumSystem &system;
    /** Another bilinear form for K, or null (B F^-1 B^T). */
    const CellStiffness *stiffness;
    const DofPartition   partition;
    StressRecovery       recovery;
    StrainLoads          strain_loads;
    /**
     * u of the last solve: on a distributed mesh with lean storage the owned
     * and ghost (relevant) dofs only, which is all that the recovery cells
     * and the rows of owned nodes read; otherwise complete, gathered after
     * every solve (a serial mesh under MPI, whose owned dofs are not a
     * contiguous range).
     */
    FieldVector u;
    /** Whether u holds only the relevant dofs (above). */
    bool                              ghosted_u = false;
    std::unique_ptr<CondensedBackEnd> back_end;
  };
} // namespace hrcontact

#endif
