#ifndef hrcontact_block_null_space_h
#define hrcontact_block_null_space_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/adaptivity/constrained_least_squares.h>

#include <vector>

namespace hrcontact
{
  /**
   * x minimising 1/2 x^T H x - g^T x subject to A x = c where the unknowns
   * come in equal blocks (the triangles of a cell's split), H is block
   * diagonal, and most rows touch one block only (a triangle's
   * equilibrium and its outer edge's traction): the null-space method in
   * two levels. Each block's own rows are eliminated by their own small
   * QR, x_b = x_b^0 + N_b y_b; the rows that couple blocks (the inner
   * edges' traction jumps) then act on the y alone, a problem of the
   * blocks' null-space dimensions (4 x 6 = 24 unknowns for four
   * triangles, against 72), solved by ConstrainedLeastSquares. About a
   * tenth of the flops of one pivoted QR of the whole 72 x 72 constraints.
   * Where the data are consistent it is the same minimiser (the caller
   * measures A x - c).
   */
  class BlockNullSpace
  {
  public:
    /** @p local_rows[b]: the rows that touch block b only; every other
     * row couples blocks. */
    void
    solve(const dealii::FullMatrix<double>             &A,
          const dealii::FullMatrix<double>             &H,
          const dealii::Vector<double>                 &g,
          const dealii::Vector<double>                 &c,
          const std::vector<std::vector<unsigned int>> &local_rows,
          dealii::Vector<double>                       &x);

  private:
    ConstrainedLeastSquares                 block, coupled;
    std::vector<dealii::FullMatrix<double>> N;
    dealii::FullMatrix<double>              A_b, B, H_y;
  };
} // namespace hrcontact

#endif
