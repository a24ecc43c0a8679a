#ifndef hrcontact_condensed_umfpack_back_end_h
#define hrcontact_condensed_umfpack_back_end_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <hrcontact/solvers/condensed/linear_back_end.h>

#include <memory>

namespace hrcontact
{
  /**
   * The serial direct back end: K as a deal.II matrix; per step K plus the
   * springs, condensed by the held rows and factorised by UMFPACK. The
   * factorisation is kept while the held rows, the springs' compliances and
   * the rows' directions stay the same (StepRows::key): a multiplier update
   * that changes no branch only moves the anchors (g + offset), the
   * right-hand side, and the next step costs a forward and back
   * substitution instead of a factorisation.
   */
  class UmfpackBackEnd : public CondensedBackEnd
  {
  public:
    UmfpackBackEnd(const EquilibriumSystem &system,
                   LinearSolverStatistics  &statistics);
    ~UmfpackBackEnd() override;

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

  private:
    /** (K + springs) condensed and factorised, for the key of its rows. */
    void
    factorise(const StepRows &rows);

    const EquilibriumSystem     &system;
    LinearSolverStatistics      &statistics;
    dealii::SparsityPattern      sparsity;
    dealii::SparseMatrix<double> K;
    struct DirectFactor;
    std::unique_ptr<DirectFactor> direct_factor;
  };
} // namespace hrcontact

#endif
