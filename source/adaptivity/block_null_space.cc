#include <hrcontact/adaptivity/block_null_space.h>

namespace hrcontact
{
  using namespace dealii;

  void
  BlockNullSpace::solve(
    const FullMatrix<double>                     &A,
    const FullMatrix<double>                     &H,
    const Vector<double>                         &g,
    const Vector<double>                         &c,
    const std::vector<std::vector<unsigned int>> &local_rows,
    Vector<double>                               &x)
  {
    const unsigned int n_blocks = local_rows.size();
    const unsigned int size     = A.n() / n_blocks;
    AssertDimension(size * n_blocks, A.n());
    // Level 1: each block's own rows, x_b = x_b^0 + N_b y_b.
    std::vector<bool> local(A.m(), false);
    N.resize(n_blocks);
    std::vector<unsigned int> offset(n_blocks + 1, 0);
    x.reinit(A.n());
    Vector<double> c_b, x_b;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        const auto &rows = local_rows[b];
        A_b.reinit(rows.size(), size);
        c_b.reinit(rows.size());
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            local[rows[i]] = true;
            c_b(i)         = c(rows[i]);
            for (unsigned int j = 0; j < size; ++j)
              A_b(i, j) = A(rows[i], b * size + j);
          }
        block.factor(A_b);
        block.row_space_solution(c_b, x_b);
        block.null_space(N[b]);
        for (unsigned int j = 0; j < size; ++j)
          x(b * size + j) = x_b(j);
        offset[b + 1] = offset[b] + N[b].n();
      }
    // Level 2: the coupling rows on y, B y = c - A x^0, with the energy
    // N^T H N (block diagonal) and N^T (g - H x^0).
    std::vector<unsigned int> coupling;
    for (unsigned int i = 0; i < A.m(); ++i)
      if (!local[i])
        coupling.push_back(i);
    const unsigned int n_y = offset[n_blocks];
    B.reinit(coupling.size(), n_y);
    Vector<double> d(coupling.size()), Hx(A.n()), g_y(n_y), y;
    for (unsigned int i = 0; i < coupling.size(); ++i)
      {
        const unsigned int row = coupling[i];
        d(i)                   = c(row);
        for (unsigned int b = 0; b < n_blocks; ++b)
          for (unsigned int j = 0; j < size; ++j)
            {
              const double a = A(row, b * size + j);
              if (a == 0)
                continue;
              d(i) -= a * x(b * size + j);
              for (unsigned int l = 0; l < N[b].n(); ++l)
                B(i, offset[b] + l) += a * N[b](j, l);
            }
      }
    H.vmult(Hx, x);
    H_y.reinit(n_y, n_y);
    FullMatrix<double> H_b(size, size), HN, NHN;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        const unsigned int k = N[b].n();
        for (unsigned int l = 0; l < k; ++l)
          for (unsigned int j = 0; j < size; ++j)
            g_y(offset[b] + l) +=
              N[b](j, l) * (g(b * size + j) - Hx(b * size + j));
        for (unsigned int i = 0; i < size; ++i)
          for (unsigned int j = 0; j < size; ++j)
            H_b(i, j) = H(b * size + i, b * size + j);
        HN.reinit(size, k);
        NHN.reinit(k, k);
        H_b.mmult(HN, N[b]);
        N[b].Tmmult(NHN, HN);
        for (unsigned int l = 0; l < k; ++l)
          for (unsigned int l2 = 0; l2 < k; ++l2)
            H_y(offset[b] + l, offset[b] + l2) = NHN(l, l2);
      }
    coupled.factor(B);
    coupled.solve(H_y, g_y, d, y);
    for (unsigned int b = 0; b < n_blocks; ++b)
      for (unsigned int j = 0; j < size; ++j)
        for (unsigned int l = 0; l < N[b].n(); ++l)
          x(b * size + j) += N[b](j, l) * y(offset[b] + l);
  }
} // namespace hrcontact
