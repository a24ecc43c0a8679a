#ifndef hrcontact_shape_factors_h
#define hrcontact_shape_factors_h

#include <deal.II/lac/full_matrix.h>

#include <hrcontact/adaptivity/block_null_space.h>

#include <vector>

namespace hrcontact
{
  /**
   * The factors of one cell shape's local problem of the error bound (the
   * constraints A, m x n, and the energy H of its first cell, of size h),
   * and the solve of many right-hand sides at once (HexahedronShapeMap's
   * 144 data columns), with one step of iterative refinement where a
   * column's constraints are off by more than 1e-11 of its data.
   */
  class ShapeFactors
  {
  public:
    /** @p local_rows: per block of unknowns (a tetrahedron) the rows that
     * touch it only (BlockNullSpace). */
    ShapeFactors(dealii::FullMatrix<double>                  &&A,
                 const dealii::FullMatrix<double>             &H,
                 const double                                  h,
                 const std::vector<std::vector<unsigned int>> &local_rows);

    /** The size of the cell the factors were computed on. */
    double h;

    unsigned int
    rank() const
    {
      return least_squares.rank();
    }
    unsigned int
    n_unknowns() const
    {
      return A.n();
    }

    /** k problems (column-major data G, n x k, and C, m x k): X (n x k)
     * and, per column, the largest entry of A x - c; A X - C itself (m x
     * k) into @p defects if given. */
    void
    solve(const std::vector<double> &G,
          const std::vector<double> &C,
          const int                  k,
          std::vector<double>       &X,
          std::vector<double>       &largest_defect,
          std::vector<double>       *defects = nullptr);

  private:
    dealii::FullMatrix<double> A;
    BlockNullSpace             least_squares;
  };
} // namespace hrcontact

#endif
