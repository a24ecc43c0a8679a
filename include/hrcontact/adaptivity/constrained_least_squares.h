#ifndef hrcontact_constrained_least_squares_h
#define hrcontact_constrained_least_squares_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace hrcontact
{
  /**
   * x minimising 1/2 x^T H x - g^T x subject to A x = c, A possibly rank
   * deficient, by the null-space method: a QR factorisation with column
   * pivoting of A^T (LAPACK dgeqp3), A = Pi R^T Q^T, fixes the part of x
   * in A's row space by a triangular solve and leaves the reduced Hessian
   * Q_2^T H Q_2 on the null space Q_2, which is small. For one problem of a
   * shape that will not be seen again (a curved mesh's cells): about a
   * tenth of the flops of an SVD and the pseudo-inverse products that
   * CellEquilibration keeps for shapes that repeat. H must be positive
   * definite on A's null space.
   */
  class ConstrainedLeastSquares
  {
  public:
    /** Factor A (m x n); rows whose pivot falls below @p tolerance times
     * the largest are treated as dependent (their data ignored). */
    void
    factor(const dealii::FullMatrix<double> &A, const double tolerance = 1e-11);

    /** The solution of A x = c in A's row space (the least-norm one),
     * after factor(). */
    void
    row_space_solution(const dealii::Vector<double> &c,
                       dealii::Vector<double>       &x) const;
    /** The same for k data at once (C: m x k, X: n x k, column-major). */
    void
    row_space_solutions(const std::vector<double> &C,
                        const int                  k,
                        std::vector<double>       &X) const;
    /** An orthonormal basis of A's null space (n x (n - rank)), after
     * factor(). */
    void
    null_space(dealii::FullMatrix<double> &N) const;

    /** The minimiser; where c is not in A's range, the dependent rows'
     * data are ignored (the caller measures A x - c). */
    void
    solve(const dealii::FullMatrix<double> &H,
          const dealii::Vector<double>     &g,
          const dealii::Vector<double>     &c,
          dealii::Vector<double>           &x);

    /** The energy's share that does not depend on g and c, for many
     * solves with one H (a shape that repeats). */
    void
    prepare(const dealii::FullMatrix<double> &H);
    /** The minimiser for the H of prepare(). */
    void
    solve(const dealii::Vector<double> &g,
          const dealii::Vector<double> &c,
          dealii::Vector<double>       &x) const;

    /** k problems at once (column-major G: n x k, C: m x k, X: n x k),
     * as matrix products: the factors are streamed from memory once for
     * all of them, not once a problem. */
    void
    solve_many(const std::vector<double> &G,
               const std::vector<double> &C,
               const int                  k,
               std::vector<double>       &X_out) const;

    unsigned int
    rank() const
    {
      return r;
    }

  private:
    int                         m = 0, n = 0, r = 0;
    std::vector<double>         qr, tau;
    mutable std::vector<double> work;
    std::vector<int>            pivots;
    /** Q_2 (n x (n - r), column-major), H Q_2 and the reduced Hessian. */
    std::vector<double> Q2, HQ2, K;
    /** Q applied to the n x k column-major block B. */
    void
    apply_q(std::vector<double> &B, const int k) const;
  };
} // namespace hrcontact

#endif
