#include <hrcontact/adaptivity/block_null_space.h>
#include <hrcontact/core/blas_lapack.h>

namespace hrcontact
{
  using namespace dealii;

  void
  BlockNullSpace::factor(const FullMatrix<double>                     &A,
                         const FullMatrix<double>                     &H,
                         const std::vector<std::vector<unsigned int>> &rows)
  {
    const unsigned int n_blocks = rows.size();
    n_rows                      = A.m();
    size                        = A.n() / n_blocks;
    AssertDimension(size * n_blocks, A.n());
    local = rows;
    // Level 1: each block's own rows, x_b = x_b^0 + N_b y_b.
    std::vector<bool> is_local(A.m(), false);
    blocks.resize(n_blocks);
    N.resize(n_blocks);
    H_b.resize(n_blocks);
    offset.assign(n_blocks + 1, 0);
    FullMatrix<double> A_b;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        A_b.reinit(rows[b].size(), size);
        for (unsigned int i = 0; i < rows[b].size(); ++i)
          {
            is_local[rows[b][i]] = true;
            for (unsigned int j = 0; j < size; ++j)
              A_b(i, j) = A(rows[b][i], b * size + j);
          }
        blocks[b].factor(A_b);
        blocks[b].null_space(N[b]);
        H_b[b].reinit(size, size);
        for (unsigned int i = 0; i < size; ++i)
          for (unsigned int j = 0; j < size; ++j)
            H_b[b](i, j) = H(b * size + i, b * size + j);
        offset[b + 1] = offset[b] + N[b].n();
      }
    // Level 2: the coupling rows on y, B y = c - A x^0, with the energy
    // N^T H N (block diagonal).
    coupling.clear();
    for (unsigned int i = 0; i < A.m(); ++i)
      if (!is_local[i])
        coupling.push_back(i);
    const unsigned int n_y = offset[n_blocks];
    A_c.reinit(coupling.size(), A.n());
    FullMatrix<double> B(coupling.size(), n_y), H_y(n_y, n_y), HN, NHN;
    for (unsigned int i = 0; i < coupling.size(); ++i)
      for (unsigned int b = 0; b < n_blocks; ++b)
        for (unsigned int j = 0; j < size; ++j)
          {
            const double a       = A(coupling[i], b * size + j);
            A_c(i, b * size + j) = a;
            if (a != 0)
              for (unsigned int l = 0; l < N[b].n(); ++l)
                B(i, offset[b] + l) += a * N[b](j, l);
          }
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        const unsigned int k = N[b].n();
        HN.reinit(size, k);
        NHN.reinit(k, k);
        H_b[b].mmult(HN, N[b]);
        N[b].Tmmult(NHN, HN);
        for (unsigned int l = 0; l < k; ++l)
          for (unsigned int l2 = 0; l2 < k; ++l2)
            H_y(offset[b] + l, offset[b] + l2) = NHN(l, l2);
      }
    coupled.factor(B);
    coupled.prepare(H_y);
  }

  void
  BlockNullSpace::solve_many(const std::vector<double> &G,
                             const std::vector<double> &C,
                             const int                  k,
                             std::vector<double>       &X) const
  {
    const int    n_blocks = blocks.size(), s = size, n = n_blocks * s;
    const int    n_y = offset[n_blocks], n_c = coupling.size();
    const double plus = 1, minus = -1, zero = 0;
    X.assign(std::size_t(n) * k, 0.);
    std::vector<double> D(std::size_t(n_c) * k), G_y(std::size_t(n_y) * k);
    std::vector<double> C_b, X_b, R_b(std::size_t(s) * k), Y_b, Y;
    // x^0 from each block's own rows (all columns at once), and the
    // reduced energy's linear term N_b^T (g_b - H_b x_b^0).
    for (int b = 0; b < n_blocks; ++b)
      {
        const int l = local[b].size(), n_b = N[b].n();
        C_b.resize(std::size_t(l) * k);
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < l; ++i)
            C_b[i + std::size_t(j) * l] =
              C[local[b][i] + std::size_t(j) * n_rows];
        blocks[b].row_space_solutions(C_b, k, X_b);
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < s; ++i)
            {
              X[b * s + i + std::size_t(j) * n] = X_b[i + std::size_t(j) * s];
              R_b[i + std::size_t(j) * s] = G[b * s + i + std::size_t(j) * n];
            }
        // H_b is symmetric: its row-major entries are H_b column-major.
        dgemm_("N",
               "N",
               &s,
               &k,
               &s,
               &minus,
               &H_b[b](0, 0),
               &s,
               X_b.data(),
               &s,
               &plus,
               R_b.data(),
               &s);
        // N_b^T R_b (N_b row-major: its entries are N_b^T column-major).
        Y_b.resize(std::size_t(n_b) * k);
        if (n_b > 0)
          dgemm_("N",
                 "N",
                 &n_b,
                 &k,
                 &s,
                 &plus,
                 &N[b](0, 0),
                 &n_b,
                 R_b.data(),
                 &s,
                 &zero,
                 Y_b.data(),
                 &n_b);
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < n_b; ++i)
            G_y[offset[b] + i + std::size_t(j) * n_y] =
              Y_b[i + std::size_t(j) * n_b];
      }
    // The coupling rows' data, c - A_c x^0 (A_c row-major: A_c^T
    // column-major).
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < n_c; ++i)
        D[i + std::size_t(j) * n_c] = C[coupling[i] + std::size_t(j) * n_rows];
    if (n_c > 0)
      dgemm_("T",
             "N",
             &n_c,
             &k,
             &n,
             &minus,
             &A_c(0, 0),
             &n,
             X.data(),
             &n,
             &plus,
             D.data(),
             &n_c);
    coupled.solve_many(G_y, D, k, Y);
    // x = x^0 + N y, block by block.
    for (int b = 0; b < n_blocks; ++b)
      {
        const int n_b = N[b].n();
        if (n_b == 0)
          continue;
        Y_b.resize(std::size_t(n_b) * k);
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < n_b; ++i)
            Y_b[i + std::size_t(j) * n_b] =
              Y[offset[b] + i + std::size_t(j) * n_y];
        // N_b (s x n_b) = (N_b^T column-major)^T.
        dgemm_("T",
               "N",
               &s,
               &k,
               &n_b,
               &plus,
               &N[b](0, 0),
               &n_b,
               Y_b.data(),
               &n_b,
               &plus,
               &X[b * s],
               &n);
      }
  }

  void
  BlockNullSpace::solve(const FullMatrix<double>                     &A,
                        const FullMatrix<double>                     &H,
                        const Vector<double>                         &g,
                        const Vector<double>                         &c,
                        const std::vector<std::vector<unsigned int>> &rows,
                        Vector<double>                               &x)
  {
    factor(A, H, rows);
    std::vector<double> X;
    solve_many(std::vector<double>(g.begin(), g.end()),
               std::vector<double>(c.begin(), c.end()),
               1,
               X);
    x.reinit(X.size());
    std::copy(X.begin(), X.end(), x.begin());
  }

  std::vector<std::vector<unsigned int>>
  BlockNullSpace::own_rows(const unsigned int n_blocks,
                           const unsigned int n_first,
                           const unsigned int n_second)
  {
    std::vector<std::vector<unsigned int>> rows(n_blocks);
    for (unsigned int k = 0; k < n_blocks; ++k)
      {
        for (unsigned int i = 0; i < n_first; ++i)
          rows[k].push_back(k * n_first + i);
        for (unsigned int i = 0; i < n_second; ++i)
          rows[k].push_back(n_blocks * n_first + k * n_second + i);
      }
    return rows;
  }

  unsigned int
  BlockNullSpace::rank() const
  {
    unsigned int r = coupled.rank();
    for (const auto &b : blocks)
      r += b.rank();
    return r;
  }
} // namespace hrcontact
