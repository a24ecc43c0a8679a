#include <hrcontact/discretisation/cell_condensation.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  void
  CellCondensation::factorise(const FullMatrix<double> &F)
  {
    n = F.m();
    m = 0;
    AssertDimension(F.n(), n);
    L.assign(n * n, 0.);
    cholesky = true;
    for (unsigned int i = 0; i < n && cholesky; ++i)
      for (unsigned int j = 0; j <= i; ++j)
        {
          double sum = F(i, j);
          for (unsigned int k = 0; k < j; ++k)
            sum -= L[i * n + k] * L[j * n + k];
          if (i == j)
            {
              // Relative to the diagonal: a pivot lost to cancellation is
              // not positive definiteness.
              if (!(sum > 1e-14 * std::abs(F(i, i))))
                {
                  cholesky = false;
                  break;
                }
              L[i * n + i] = std::sqrt(sum);
            }
          else
            L[i * n + j] = sum / L[j * n + j];
        }
    if (!cholesky)
      {
        F_inverse.reinit(n, n);
        F_inverse.invert(F);
      }
  }

  void
  CellCondensation::factorise(const FullMatrix<double> &F,
                              const FullMatrix<double> &B)
  {
    factorise(F);
    m = B.m();
    AssertDimension(B.n(), n);
    Y.resize(n * m);
    if (!cholesky)
      {
        FullMatrix<double> R(n, m);
        F_inverse.mTmult(R, B);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int a = 0; a < m; ++a)
            Y[i * m + a] = R(i, a);
        K_fallback.reinit(m, m);
        B.mmult(K_fallback, R);
        return;
      }
    // Y = L^{-1} B^T by forward substitution, column a from row a of B.
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int i = 0; i < n; ++i)
        {
          double sum = B(a, i);
          for (unsigned int k = 0; k < i; ++k)
            sum -= L[i * n + k] * Y[k * m + a];
          Y[i * m + a] = sum / L[i * n + i];
        }
  }

  void
  CellCondensation::stiffness(FullMatrix<double> &K) const
  {
    if (!cholesky)
      {
        K = K_fallback;
        return;
      }
    K.reinit(m, m);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int c = 0; c <= a; ++c)
        {
          double sum = 0;
          for (unsigned int i = 0; i < n; ++i)
            sum += Y[i * m + a] * Y[i * m + c];
          K(a, c) = sum;
          K(c, a) = sum;
        }
  }

  void
  CellCondensation::recovery(FullMatrix<double> &R) const
  {
    R.reinit(n, m);
    if (!cholesky)
      {
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int a = 0; a < m; ++a)
            R(i, a) = Y[i * m + a];
        return;
      }
    // R = L^{-T} Y by back substitution.
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int i = n; i-- > 0;)
        {
          double sum = Y[i * m + a];
          for (unsigned int k = i + 1; k < n; ++k)
            sum -= L[k * n + i] * R(k, a);
          R(i, a) = sum / L[i * n + i];
        }
  }

  void
  CellCondensation::solve(const Vector<double> &y, Vector<double> &x) const
  {
    AssertDimension(y.size(), n);
    x.reinit(n);
    if (!cholesky)
      {
        F_inverse.vmult(x, y);
        return;
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        double sum = y[i];
        for (unsigned int k = 0; k < i; ++k)
          sum -= L[i * n + k] * x[k];
        x[i] = sum / L[i * n + i];
      }
    for (unsigned int i = n; i-- > 0;)
      {
        double sum = x[i];
        for (unsigned int k = i + 1; k < n; ++k)
          sum -= L[k * n + i] * x[k];
        x[i] = sum / L[i * n + i];
      }
  }
} // namespace hrcontact
