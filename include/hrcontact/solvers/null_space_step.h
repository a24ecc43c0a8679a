#ifndef hrcontact_null_space_step_h
#define hrcontact_null_space_step_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <vector>

namespace hrcontact
{
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
} // namespace hrcontact

#endif
