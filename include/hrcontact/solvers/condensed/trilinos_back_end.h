#ifndef hrcontact_condensed_trilinos_back_end_h
#define hrcontact_condensed_trilinos_back_end_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hrcontact/solvers/condensed/linear_back_end.h>

#include <vector>

namespace hrcontact
{
  /**
   * What the Trilinos back ends share (TrilinosCgAmg, TrilinosMumps): K
   * assembled cell by cell into a distributed Trilinos matrix over the
   * DofPartition (every cell this process owns, the held rows' constraints
   * applied while assembling, as in step-40), and after the solve u on this
   * process's relevant dofs, or gathered whole (a serial mesh under MPI).
   *
   * The part of K that no Newton step changes is K_c summed over the owned
   * cells none of whose dofs belongs to the node of a Q or H row (held
   * rows, springs and their constraints touch only the cells at those
   * nodes). It is assembled once into `matrix`; a step changes only the
   * rows of the kept cells' dofs, so it restores their fixed values (kept
   * row after row, with Epetra's local row numbers) and adds the kept
   * cells, instead of copying a second matrix of the fixed part: one matrix
   * fewer per process, and the same values to the last bit.
   */
  class TrilinosBackEnd : public CondensedBackEnd
  {
  public:
    TrilinosBackEnd(const EquilibriumSystem    &system,
                    const LinearSolverSettings &settings,
                    const DofPartition         &partition,
                    const bool                  ghosted_u,
                    LinearSolverStatistics     &statistics);

    void
    assemble(
      const std::function<void(dealii::DynamicSparsityPattern &)> &couplings,
      const std::function<void(const CellStiffnessSink &)> &cells) override;
    void
    solve(const StepRows    &rows,
          const StrainLoads &loads,
          FieldVector       &u) override;
    void
    rows_changed() override;
    void
    flexibility_changed() override;

  protected:
    /** Solve matrix x = rhs, x holding the start. */
    virtual void
    solve_assembled() = 0;
    /** The matrix is about to change (other held rows or springs). */
    virtual void
    matrix_changing() = 0;
    /** K is assembled again: drop everything built from the old one (ML
     * keeps a pointer to the matrix that assemble() replaces). */
    virtual void
    drop_matrix_dependents() = 0;

    /** The values of changing_rows, row after row. */
    std::vector<double>
    row_values() const;
    /** Write @p values (row_values' layout) into changing_rows. */
    void
    set_row_values(const std::vector<double> &values) const;
    /** Exchange the values of changing_rows with those in @p values. */
    void
    swap_row_values(std::vector<double> &values) const;

    const EquilibriumSystem               &system;
    const LinearSolverSettings             settings;
    const DofPartition                    &partition;
    LinearSolverStatistics                &statistics;
    dealii::TrilinosWrappers::SparseMatrix matrix;
    dealii::TrilinosWrappers::MPI::Vector  rhs, x;

  private:
    /** The kept cells' K_c and the springs into the matrix (or only their
     * constraints' inhomogeneities into rhs, with @p same_matrix), and the
     * loads into rhs. */
    void
    assemble_step(const StepRows    &rows,
                  const StrainLoads &loads,
                  const bool         same_matrix);
    /** f(values, n) on the stored values of each of changing_rows. */
    template <typename F>
    void
    for_each_changing_row(const F &f) const;

    const bool ghosted_u;
    /** The owned rows the kept cells (and held pair rows) change, and
     * their values in the fixed part. */
    std::vector<int>    changing_rows;
    std::vector<double> fixed_values;
    /** The displacement dofs and K_c of the other owned cells, those at Q
     * and H rows, one cell after the other (dofs_per_cell and its square
     * numbers each). */
    unsigned int                                 dofs_per_cell = 0;
    std::vector<dealii::types::global_dof_index> cell_dofs;
    std::vector<double>                          cell_stiffness;
    /**
     * StepRows::key of the held rows and springs `matrix` was assembled
     * for. A multiplier update that keeps every branch and penalty changes
     * only the right-hand side: the next step keeps the matrix and what the
     * back end built on it.
     */
    std::vector<double> matrix_key;
    bool                assembled = false;
    /** `matrix` has its sparsity pattern (the mesh's couplings, which no
     * material step changes). */
    bool pattern_built = false;
  };
} // namespace hrcontact

#endif
