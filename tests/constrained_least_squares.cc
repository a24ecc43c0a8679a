// ConstrainedLeastSquares (the error bound's direct path on shapes met
// once): x minimising 1/2 x^T H x - g^T x with A x = c must equal the
// minimiser built independently from the SVD of A (pseudo-inverse and null
// space, deal.II's LAPACKFullMatrix) to round-off, for the sizes of the
// cell problems (72 x 72 of rank 69, as a four-triangle split; 108 x 108 of
// rank 104, six triangles) and for full row rank (40 x 72); A x = c must
// hold where c is in A's range; the KKT condition (H x - g orthogonal to
// A's null space) must hold; and an energy that is not positive definite
// on the null space must be refused by name; several data at once
// (solve_many) must give each one's own x; BlockNullSpace (a cell's
// triangles' own rows first, then the rows that couple them) must give
// the x of ConstrainedLeastSquares on a random problem of that structure.

#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <hrcontact/adaptivity/block_null_space.h>
#include <hrcontact/adaptivity/constrained_least_squares.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "tests.h"

using namespace dealii;

struct Problem
{
  FullMatrix<double> A, H;
  Vector<double>     g, c;
};

/** A of rank @p rank (a product of random factors), H block diagonal with
 * 18 x 18 positive definite blocks (or with a negative one), c in A's
 * range. */
Problem
random_problem(const unsigned int m,
               const unsigned int n,
               const unsigned int rank,
               const bool         definite,
               std::mt19937      &random)
{
  std::uniform_real_distribution<double> uniform(-1., 1.);
  Problem                                p;
  FullMatrix<double>                     B(m, rank), C(rank, n);
  for (auto &b : B)
    b = uniform(random);
  for (auto &v : C)
    v = uniform(random);
  p.A.reinit(m, n);
  B.mmult(p.A, C);
  p.H.reinit(n, n);
  for (unsigned int start = 0; start < n; start += 18)
    {
      const unsigned int size = std::min(18u, n - start);
      FullMatrix<double> D(size, size);
      for (auto &d : D)
        d = uniform(random);
      for (unsigned int i = 0; i < size; ++i)
        for (unsigned int j = 0; j < size; ++j)
          {
            double sum = i == j ? (definite ? 0.5 : -40.) : 0.;
            for (unsigned int k = 0; k < size; ++k)
              sum += D(i, k) * D(j, k);
            p.H(start + i, start + j) = sum;
          }
    }
  Vector<double> x0(n);
  for (auto &v : x0)
    v = uniform(random);
  p.c.reinit(m);
  p.A.vmult(p.c, x0);
  p.g.reinit(n);
  for (auto &v : p.g)
    v = uniform(random);
  return p;
}

/** The minimiser from the SVD: x = A^+ c + N (N^T H N)^-1 N^T (g - H A^+
 * c); N, the null space, also returned. */
Vector<double>
reference(const Problem &p, FullMatrix<double> &N)
{
  const unsigned int       m = p.A.m(), n = p.A.n();
  LAPACKFullMatrix<double> svd(m, n);
  svd = p.A;
  svd.compute_svd();
  unsigned int rank = 0;
  while (rank < std::min(m, n) &&
         svd.singular_value(rank) > 1e-11 * svd.singular_value(0))
    ++rank;
  const auto    &U  = svd.get_svd_u();
  const auto    &VT = svd.get_svd_vt();
  Vector<double> x(n), Hx(n), r(n - rank);
  for (unsigned int l = 0; l < rank; ++l)
    {
      double u_c = 0;
      for (unsigned int j = 0; j < m; ++j)
        u_c += U(j, l) * p.c(j);
      for (unsigned int i = 0; i < n; ++i)
        x(i) += VT(l, i) * u_c / svd.singular_value(l);
    }
  N.reinit(n, n - rank);
  for (unsigned int l = rank; l < n; ++l)
    for (unsigned int i = 0; i < n; ++i)
      N(i, l - rank) = VT(l, i);
  FullMatrix<double> HN(n, n - rank), K(n - rank, n - rank);
  p.H.mmult(HN, N);
  N.Tmmult(K, HN);
  K.gauss_jordan();
  p.H.vmult(Hx, x);
  Vector<double> rhs(p.g), z(n - rank), y(n - rank);
  rhs -= Hx;
  N.Tvmult(y, rhs);
  K.vmult(z, y);
  N.vmult_add(x, z);
  return x;
}

void
compare(const unsigned int m,
        const unsigned int n,
        const unsigned int rank,
        std::mt19937      &random)
{
  const Problem p = random_problem(m, n, rank, true, random);
  hrcontact::ConstrainedLeastSquares least_squares;
  least_squares.factor(p.A);
  Vector<double> x;
  least_squares.solve(p.H, p.g, p.c, x);
  FullMatrix<double>   N;
  const Vector<double> x_ref = reference(p, N);
  Vector<double>       dx(x), Ax(m), Hx(n), kkt(N.n());
  dx -= x_ref;
  p.A.vmult(Ax, x);
  Ax -= p.c;
  p.H.vmult(Hx, x);
  Hx -= p.g;
  N.Tvmult(kkt, Hx);
  // Several data at once (HexahedronShapeMap's columns): (g, c) and
  // (-g, 2c) give x and the second problem's own solution.
  std::vector<double> G(2 * n), C(2 * m), X;
  for (unsigned int i = 0; i < n; ++i)
    {
      G[i]     = p.g(i);
      G[n + i] = -p.g(i);
    }
  for (unsigned int i = 0; i < m; ++i)
    {
      C[i]     = p.c(i);
      C[m + i] = 2 * p.c(i);
    }
  least_squares.solve_many(G, C, 2, X);
  Vector<double> minus_g(p.g), two_c(p.c), x2;
  minus_g *= -1;
  two_c *= 2;
  least_squares.solve(minus_g, two_c, x2);
  double many = 0;
  for (unsigned int i = 0; i < n; ++i)
    many = std::max({many,
                     std::abs(X[i] - x(i)) / x.linfty_norm(),
                     std::abs(X[n + i] - x2(i)) / x2.linfty_norm()});
  std::cout << m << " x " << n << " of rank " << rank
            << ": rank found: " << least_squares.rank()
            << "\n  x as from the SVD (1e-10): "
            << hrcontact_tests::check(dx.l2_norm() / x_ref.l2_norm(), 1e-10)
            << "\n  A x = c (1e-12): "
            << hrcontact_tests::check(Ax.l2_norm() / p.c.l2_norm(), 1e-12)
            << "\n  N^T (H x - g) = 0 (1e-10): "
            << hrcontact_tests::check(kkt.l2_norm() / p.g.l2_norm(), 1e-10)
            << "\n  the same two at once by solve_many (1e-12): "
            << hrcontact_tests::check(many, 1e-12) << std::endl;
}

/** Four blocks of 18 unknowns, 12 rows of each block's own (one of them
 * dependent on the others, as a split's can be), then 20 rows that couple
 * neighbouring blocks and 3 that are combinations of all rows (the rigid
 * motions' dependencies): BlockNullSpace against ConstrainedLeastSquares. */
void
blocks(std::mt19937 &random)
{
  std::uniform_real_distribution<double> uniform(-1., 1.);
  Problem            p       = random_problem(72, 72, 72, true, random);
  const unsigned int n_local = 12, n_coupling = 20;
  FullMatrix<double> A(4 * n_local + n_coupling + 3, 72);
  std::vector<std::vector<unsigned int>> local_rows(4);
  for (unsigned int b = 0; b < 4; ++b)
    for (unsigned int i = 0; i < n_local; ++i)
      {
        const unsigned int row = b * n_local + i;
        local_rows[b].push_back(row);
        for (unsigned int j = 0; j < 18; ++j)
          A(row, 18 * b + j) =
            i + 1 < n_local ?
              uniform(random) :
              A(b * n_local, 18 * b + j) - A(b * n_local + 1, 18 * b + j);
      }
  for (unsigned int i = 0; i < n_coupling; ++i)
    {
      const unsigned int row = 4 * n_local + i, b = i % 4;
      for (unsigned int j = 0; j < 18; ++j)
        {
          A(row, 18 * b + j)             = uniform(random);
          A(row, 18 * ((b + 1) % 4) + j) = uniform(random);
        }
    }
  for (unsigned int k = 0; k < 3; ++k)
    for (unsigned int i = 0; i < 4 * n_local + n_coupling; ++i)
      {
        const double w = uniform(random);
        for (unsigned int j = 0; j < 72; ++j)
          A(4 * n_local + n_coupling + k, j) += w * A(i, j);
      }
  Vector<double> x0(72), c(A.m()), x_block, x_whole;
  for (auto &v : x0)
    v = uniform(random);
  A.vmult(c, x0);
  hrcontact::BlockNullSpace().solve(A, p.H, p.g, c, local_rows, x_block);
  hrcontact::ConstrainedLeastSquares whole;
  whole.factor(A);
  whole.solve(p.H, p.g, c, x_whole);
  Vector<double> Ax(A.m());
  A.vmult(Ax, x_block);
  Ax -= c;
  x_block -= x_whole;
  std::cout << "blocks (4 x 18 unknowns, " << A.m() << " rows, rank "
            << whole.rank() << "): the whole problem's x (1e-10): "
            << hrcontact_tests::check(x_block.l2_norm() / x_whole.l2_norm(),
                                      1e-10)
            << ", A x = c (1e-12): "
            << hrcontact_tests::check(Ax.l2_norm() / c.l2_norm(), 1e-12)
            << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::mt19937                     random(5);
  compare(72, 72, 69, random);
  compare(108, 108, 104, random);
  compare(40, 72, 40, random);
  blocks(random);
  // Negative definite blocks of H: the reduced Hessian is not positive
  // definite.
  const Problem p = random_problem(72, 72, 60, false, random);
  hrcontact::ConstrainedLeastSquares least_squares;
  least_squares.factor(p.A);
  Vector<double> x;
  try
    {
      least_squares.solve(p.H, p.g, p.c, x);
      std::cout << "indefinite energy: NOT refused" << std::endl;
    }
  catch (const std::exception &e)
    {
      const std::string what = e.what();
      std::cout << "indefinite energy refused: "
                << (what.find("not positive definite") != std::string::npos ?
                      "yes, by name" :
                      "without the name")
                << std::endl;
    }
}
