#ifndef hrcontact_condensed_trilinos_mumps_h
#define hrcontact_condensed_trilinos_mumps_h

#include <hrcontact/solvers/condensed/mumps_factor.h>
#include <hrcontact/solvers/condensed/trilinos_back_end.h>

#include <memory>


namespace hrcontact
{
  /**
   * MUMPS (Solver = direct on several processes), called as MumpsFactor
   * says (not through Amesos, which cannot declare the matrix SPD).
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

    /** MUMPS's instance: the symbolic analysis of the pattern, and the
     * numeric factors of the last values. */
    std::unique_ptr<MumpsFactor> factor;
    /** The numeric factors are those of the current values. */
    bool factorised = false;
  };
} // namespace hrcontact

#endif
