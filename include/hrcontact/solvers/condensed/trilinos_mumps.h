#ifndef hrcontact_condensed_trilinos_mumps_h
#define hrcontact_condensed_trilinos_mumps_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <hrcontact/solvers/condensed/trilinos_back_end.h>

#include <memory>

namespace hrcontact
{
  /**
   * MUMPS through Trilinos Amesos (Solver = direct on several processes).
   * The factor is kept while the matrix is: a step that changes only the
   * right-hand side costs a forward and back substitution, as with
   * UmfpackBackEnd's factor.
   */
  class TrilinosMumps : public TrilinosBackEnd
  {
  public:
    using TrilinosBackEnd::TrilinosBackEnd;

  private:
    void
    solve_assembled() override;
    void
    matrix_changing() override;
    void
    drop_matrix_dependents() override;

    /** Amesos keeps a pointer to `matrix` and the solver one to its
     * control. */
    std::unique_ptr<dealii::SolverControl>                  direct_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> direct_solver;
  };
} // namespace hrcontact

#endif
