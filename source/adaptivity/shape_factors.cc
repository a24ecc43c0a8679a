#include <hrcontact/adaptivity/shape_factors.h>
#include <hrcontact/core/blas_lapack.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  ShapeFactors::ShapeFactors(
    FullMatrix<double>                          &&A_,
    const FullMatrix<double>                     &H,
    const double                                  h,
    const std::vector<std::vector<unsigned int>> &local_rows)
    : h(h)
    , A(std::move(A_))
  {
    least_squares.factor(A, H, local_rows);
  }

  void
  ShapeFactors::solve(const std::vector<double> &G,
                      const std::vector<double> &C,
                      const int                  k,
                      std::vector<double>       &X,
                      std::vector<double>       &largest_defect,
                      std::vector<double>       *defects)
  {
    const int           m = A.m(), n = A.n();
    std::vector<double> R(m * k);
    least_squares.solve_many(G, C, k, X);
    // A X - C (A's row-major entries are A^T column-major), and per column
    // its size relative to the data.
    const auto defect = [&](std::vector<double> &relative) {
      R                 = C;
      const double plus = 1, minus = -1;
      dgemm_("T",
             "N",
             &m,
             &k,
             &n,
             &plus,
             &A(0, 0),
             &n,
             X.data(),
             &n,
             &minus,
             R.data(),
             &m);
      relative.assign(k, 0.);
      for (int j = 0; j < k; ++j)
        {
          double r2 = 0, c2 = 0;
          for (int i = 0; i < m; ++i)
            {
              r2 += R[i + j * m] * R[i + j * m];
              c2 += C[i + j * m] * C[i + j * m];
            }
          relative[j] = std::sqrt(r2 / std::max(c2, 1e-300));
        }
    };
    std::vector<double> relative;
    defect(relative);
    // Where R_11 is ill conditioned and a column's constraints are off by
    // more than 1e-11 of its data, one step of refinement (the minimiser
    // is linear in the data) for all.
    if (*std::max_element(relative.begin(), relative.end()) > 1e-11)
      {
        std::vector<double> zero(n * k, 0.), minus_R(R), correction;
        for (double &v : minus_R)
          v = -v;
        least_squares.solve_many(zero, minus_R, k, correction);
        for (int i = 0; i < n * k; ++i)
          X[i] += correction[i];
        defect(relative);
      }
    if (defects)
      *defects = R;
    largest_defect.assign(k, 0.);
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < m; ++i)
        largest_defect[j] = std::max(largest_defect[j], std::abs(R[i + j * m]));
  }
} // namespace hrcontact
