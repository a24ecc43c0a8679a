#ifndef hrcontact_cell_condensation_h
#define hrcontact_cell_condensation_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace hrcontact
{
  /**
   * One cell's static condensation of the stresses (doc/method.md, the
   * condensed path): with the cell's compliance block F_c (stress dofs
   * squared, symmetric positive definite) and its equilibrium block B_c
   * (displacement dofs x stress dofs), the cell stiffness K_c = B_c F_c^{-1}
   * B_c^T, the stress recovery R = F_c^{-1} B_c^T (s_c = R u_c) and
   * F_c^{-1} y for a strain term.
   *
   * All three from the Cholesky factor F_c = L L^T: Y = L^{-1} B_c^T, K_c =
   * Y^T Y, R = L^{-T} Y. That is about a quarter of the work of inverting
   * F_c and multiplying (Hertz refinement 7: the condensed path's cell loop
   * took 2.2-2.6 times the Q1 floor's instead of 3.2 times). Written here
   * rather than through LAPACK: the blocks are 12 x 12 (48 x 48 in 3D), where
   * a call costs more than the arithmetic; and rather than with
   * FullMatrix::cholesky, which accepts a zero pivot and has no triangular
   * solves for several right-hand sides. A block that is not positive
   * definite to round-off (a degenerate compliance) falls back to the
   * inverse, which gives the same products where it exists.
   */
  class CellCondensation
  {
  public:
    /** Factorise F (n x n) and form Y from B (m x n): for stiffness() and
     * recovery(). */
    void
    factorise(const dealii::FullMatrix<double> &F,
              const dealii::FullMatrix<double> &B);

    /** Factorise F only: for solve() alone (the final stress recovery),
     * without the work of Y. */
    void
    factorise(const dealii::FullMatrix<double> &F);

    /** K_c = B F^{-1} B^T (m x m), symmetric. */
    void
    stiffness(dealii::FullMatrix<double> &K) const;

    /** R = F^{-1} B^T (n x m). */
    void
    recovery(dealii::FullMatrix<double> &R) const;

    /** x = F^{-1} y. */
    void
    solve(const dealii::Vector<double> &y, dealii::Vector<double> &x) const;

    /** Whether the last factorise() took the Cholesky factor (F positive
     * definite) rather than the inverse. */
    bool
    positive_definite() const
    {
      return cholesky;
    }

  private:
    unsigned int n = 0, m = 0;
    bool         cholesky = true;
    /** L row by row (lower triangle), and Y = L^{-1} B^T row by row (n x
     * m); without the factor, Y holds R. */
    std::vector<double> L, Y;
    /** Without the factor: F^{-1} and K_c. */
    dealii::FullMatrix<double> F_inverse, K_fallback;
  };
} // namespace hrcontact

#endif
