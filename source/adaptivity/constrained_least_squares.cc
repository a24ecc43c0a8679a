#include <deal.II/base/exceptions.h>

#include <hrcontact/adaptivity/constrained_least_squares.h>
#include <hrcontact/core/blas_lapack.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  void
  ConstrainedLeastSquares::factor(const FullMatrix<double> &A,
                                  const double              tolerance)
  {
    m = A.m();
    n = A.n();
    // A is row-major, so its entries are A^T column-major (n x m).
    qr.assign(&A(0, 0), &A(0, 0) + m * n);
    pivots.assign(m, 0);
    tau.resize(std::min(m, n));
    int       info  = 0;
    const int query = -1;
    double    size  = 0;
    dgeqp3_(
      &n, &m, qr.data(), &n, pivots.data(), tau.data(), &size, &query, &info);
    work.resize(std::max<std::size_t>(std::lround(size), 4 * n));
    const int lwork = work.size();
    dgeqp3_(&n,
            &m,
            qr.data(),
            &n,
            pivots.data(),
            tau.data(),
            work.data(),
            &lwork,
            &info);
    AssertThrow(info == 0, ExcMessage("dgeqp3 failed"));
    r                    = 0;
    const double largest = std::abs(qr[0]);
    while (r < std::min(m, n) && std::abs(qr[r + r * n]) > tolerance * largest)
      ++r;
  }

  void
  ConstrainedLeastSquares::apply_q(std::vector<double> &B, const int k) const
  {
    int       info  = 0;
    const int n_ref = tau.size();
    if (work.size() < 64u * k)
      work.resize(64u * k);
    const int lwork = work.size();
    dormqr_("L",
            "N",
            &n,
            &k,
            &n_ref,
            qr.data(),
            &n,
            tau.data(),
            B.data(),
            &n,
            work.data(),
            &lwork,
            &info);
    AssertThrow(info == 0, ExcMessage("dormqr failed"));
  }

  void
  ConstrainedLeastSquares::solve(const FullMatrix<double> &H,
                                 const Vector<double>     &g,
                                 const Vector<double>     &c,
                                 Vector<double>           &x)
  {
    prepare(H);
    solve(g, c, x);
  }

  void
  ConstrainedLeastSquares::solve_many(const std::vector<double> &G,
                                      const std::vector<double> &C,
                                      const int                  k,
                                      std::vector<double>       &X_out) const
  {
    row_space_solutions(C, k, X_out);
    const double plus = 1, minus = -1, zero = 0;
    const int    n_null = n - r;
    if (n_null == 0)
      return;
    std::vector<double> Z(n_null * k);
    dgemm_("T",
           "N",
           &n_null,
           &k,
           &n,
           &plus,
           Q2.data(),
           &n,
           G.data(),
           &n,
           &zero,
           Z.data(),
           &n_null);
    dgemm_("T",
           "N",
           &n_null,
           &k,
           &n,
           &minus,
           HQ2.data(),
           &n,
           X_out.data(),
           &n,
           &plus,
           Z.data(),
           &n_null);
    int info = 0;
    dpotrs_("L", &n_null, &k, K.data(), &n_null, Z.data(), &n_null, &info);
    dgemm_("N",
           "N",
           &n,
           &k,
           &n_null,
           &plus,
           Q2.data(),
           &n,
           Z.data(),
           &n_null,
           &plus,
           X_out.data(),
           &n);
  }

  void
  ConstrainedLeastSquares::prepare(const FullMatrix<double> &H)
  {
    // Q_2 = Q (0; I), H Q_2 and the reduced Hessian K = Q_2^T H Q_2.
    const int k = n - r;
    Q2.assign(n * k, 0.);
    HQ2.assign(n * k, 0.);
    K.assign(k * k, 0.);
    if (k == 0)
      return;
    for (int j = 0; j < k; ++j)
      Q2[r + j + j * n] = 1;
    apply_q(Q2, k);
    // H is symmetric: its row-major entries are H column-major.
    const double plus = 1, zero = 0;
    dgemm_("N",
           "N",
           &n,
           &k,
           &n,
           &plus,
           &H(0, 0),
           &n,
           Q2.data(),
           &n,
           &zero,
           HQ2.data(),
           &n);
    dgemm_("T",
           "N",
           &k,
           &k,
           &n,
           &plus,
           Q2.data(),
           &n,
           HQ2.data(),
           &n,
           &zero,
           K.data(),
           &k);
    int info = 0;
    dpotrf_("L", &k, K.data(), &k, &info);
    AssertThrow(info == 0,
                ExcMessage("the energy is not positive definite on the "
                           "admissible stresses' null space"));
  }

  void
  ConstrainedLeastSquares::row_space_solution(const Vector<double> &c,
                                              Vector<double>       &x) const
  {
    // R11^T w_1 = (Pi^T c)_1 by forward substitution (R is the upper
    // triangle of qr); x_1 = Q (w_1, 0).
    std::vector<double> w(n, 0.);
    for (int i = 0; i < r; ++i)
      w[i] = c(pivots[i] - 1);
    const int one = 1;
    if (r > 0)
      dtrsv_("U", "T", "N", &r, qr.data(), &n, w.data(), &one);
    apply_q(w, 1);
    x.reinit(n);
    std::copy(w.begin(), w.end(), x.begin());
  }

  void
  ConstrainedLeastSquares::row_space_solutions(const std::vector<double> &C,
                                               const int                  k,
                                               std::vector<double> &X) const
  {
    // R_11^T W = (Pi^T C)_r and X = Q (W; 0), all columns at once.
    X.assign(std::size_t(n) * k, 0.);
    std::vector<double> W(std::size_t(r) * k);
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < r; ++i)
        W[i + j * r] = C[pivots[i] - 1 + std::size_t(j) * m];
    const double plus = 1;
    if (r > 0)
      dtrsm_("L", "U", "T", "N", &r, &k, &plus, qr.data(), &n, W.data(), &r);
    for (int j = 0; j < k; ++j)
      std::copy(W.begin() + std::size_t(j) * r,
                W.begin() + std::size_t(j + 1) * r,
                X.begin() + std::size_t(j) * n);
    apply_q(X, k);
  }

  void
  ConstrainedLeastSquares::null_space(FullMatrix<double> &N) const
  {
    const int           k = n - r;
    std::vector<double> B(std::size_t(n) * k, 0.);
    for (int j = 0; j < k; ++j)
      B[r + j + j * n] = 1;
    if (k > 0)
      apply_q(B, k);
    N.reinit(n, k);
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < n; ++i)
        N(i, j) = B[i + j * n];
  }

  void
  ConstrainedLeastSquares::solve(const Vector<double> &g,
                                 const Vector<double> &c,
                                 Vector<double>       &x) const
  {
    row_space_solution(c, x);
    const int    one  = 1;
    const double plus = 1, minus = -1, zero = 0;
    const int    k = n - r;
    if (k == 0)
      return;
    // The null space's part: K z = Q_2^T g - (H Q_2)^T x_1 (H symmetric).
    std::vector<double> z(k, 0.);
    dgemv_("T",
           &n,
           &k,
           &plus,
           Q2.data(),
           &n,
           g.begin(),
           &one,
           &zero,
           z.data(),
           &one);
    dgemv_("T",
           &n,
           &k,
           &minus,
           HQ2.data(),
           &n,
           x.begin(),
           &one,
           &plus,
           z.data(),
           &one);
    int info = 0;
    dpotrs_("L", &k, &one, K.data(), &k, z.data(), &k, &info);
    dgemv_("N",
           &n,
           &k,
           &plus,
           Q2.data(),
           &n,
           z.data(),
           &one,
           &plus,
           x.begin(),
           &one);
  }
} // namespace hrcontact
