#ifndef hrcontact_condensed_trilinos_mumps_h
#define hrcontact_condensed_trilinos_mumps_h

#include <hrcontact/solvers/condensed/trilinos_back_end.h>

#include <memory>

#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>

namespace hrcontact
{
  /**
   * MUMPS through Trilinos Amesos (Solver = direct on several processes).
   * The factor is kept while the matrix is: a step that changes only the
   * right-hand side costs a forward and back substitution, as with
   * UmfpackBackEnd's factor. A step that changes the values (held rows,
   * a material step's F_c) is factorised numerically on the symbolic
   * analysis of the first: the pattern does not change.
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

    /** Amesos keeps a pointer to the problem, the problem to `matrix`
     * (whose pattern TrilinosBackEnd keeps): the symbolic analysis stays
     * valid while the values change. */
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    solver;
    /** The numeric factors are those of the current values. */
    bool factorised = false;
  };
} // namespace hrcontact

#endif
