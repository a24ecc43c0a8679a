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
   * come in equal blocks (the triangles or tetrahedra of a cell's split),
   * H is block diagonal, and most rows touch one block only (its
   * equilibrium, its outer face's traction): the null-space method in two
   * levels. Each block's own rows are eliminated by their own small QR,
   * x_b = x_b^0 + N_b y_b; the rows that couple blocks (the inner faces'
   * traction jumps) then act on the y alone, a problem of the blocks'
   * null-space dimensions (2D: 24 unknowns instead of 72; 3D: 720 instead
   * of 1,440), solved by ConstrainedLeastSquares. Where the data are
   * consistent it is the same minimiser (the caller measures A x - c).
   */
  class BlockNullSpace
  {
  public:
    /** @p local_rows[b]: the rows that touch block b only; every other
     * row couples blocks. */
    void
    factor(const dealii::FullMatrix<double>             &A,
           const dealii::FullMatrix<double>             &H,
           const std::vector<std::vector<unsigned int>> &local_rows);

    /** k problems at once (column-major G: n x k, C: m x k, X: n x k). */
    void
    solve_many(const std::vector<double> &G,
               const std::vector<double> &C,
               const int                  k,
               std::vector<double>       &X) const;

    /** factor() and one solve. */
    void
    solve(const dealii::FullMatrix<double>             &A,
          const dealii::FullMatrix<double>             &H,
          const dealii::Vector<double>                 &g,
          const dealii::Vector<double>                 &c,
          const std::vector<std::vector<unsigned int>> &local_rows,
          dealii::Vector<double>                       &x);

    /** The own rows of @p n_blocks blocks where the constraints list
     * first @p n_first rows per block (equilibrium), then @p n_second per
     * block (its outer face's traction), then the coupling rows: the
     * order of both splits' constraints. */
    static std::vector<std::vector<unsigned int>>
    own_rows(const unsigned int n_blocks,
             const unsigned int n_first,
             const unsigned int n_second);

    /** The rank of A (the blocks' and the coupling rows'). */
    unsigned int
    rank() const;

  private:
    unsigned int                            n_rows = 0, size = 0;
    std::vector<std::vector<unsigned int>>  local;
    std::vector<unsigned int>               coupling, offset;
    std::vector<ConstrainedLeastSquares>    blocks;
    std::vector<dealii::FullMatrix<double>> N, H_b;
    /** The coupling rows of A. */
    dealii::FullMatrix<double> A_c;
    ConstrainedLeastSquares    coupled;
  };
} // namespace hrcontact

#endif
