// CellCondensation: the condensed path's K_c = B F^-1 B^T, R = F^-1 B^T and
// F^-1 y from the Cholesky factor of F must equal those from the inverse
// (deal.II's FullMatrix::invert) to round-off, for the sizes of DGQ1 cells
// in 2D (12 stress x 8 displacement dofs) and 3D (48 x 24), at the scale
// of a steel compliance (1e-11); a block that is not positive definite
// must fall back to the inverse and still give its products.

#include <deal.II/base/mpi.h>

#include <hrcontact/discretisation/cell_condensation.h>

#include <iostream>
#include <random>

#include "tests.h"

using namespace dealii;

double
relative_difference(const FullMatrix<double> &a, const FullMatrix<double> &b)
{
  FullMatrix<double> d(a);
  d.add(-1., b);
  return d.frobenius_norm() / b.frobenius_norm();
}

void
compare(const unsigned int n,
        const unsigned int m,
        const bool         definite,
        std::mt19937      &random)
{
  std::uniform_real_distribution<double> uniform(-1., 1.);
  // F = scale (A A^T + n I): symmetric positive definite, condition about
  // 1e2; or with a negative eigenvalue (definite = false).
  FullMatrix<double> A(n, n), F(n, n), B(m, n);
  for (auto &a : A)
    a = uniform(random);
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      {
        double sum = 0;
        for (unsigned int k = 0; k < n; ++k)
          sum += A(i, k) * A(j, k);
        F(i, j) = 1e-11 * (sum + (i == j ? (definite ? 1. : -4.) * n : 0.));
      }
  for (auto &b : B)
    b = uniform(random);
  Vector<double> y(n);
  for (auto &v : y)
    v = uniform(random);

  FullMatrix<double> F_inverse(n, n), R_ref(n, m), K_ref(m, m);
  F_inverse.invert(F);
  F_inverse.mTmult(R_ref, B);
  B.mmult(K_ref, R_ref);
  Vector<double> x_ref(n);
  F_inverse.vmult(x_ref, y);

  hrcontact::CellCondensation condensation;
  condensation.factorise(F, B);
  FullMatrix<double> K, R;
  condensation.stiffness(K);
  condensation.recovery(R);
  Vector<double> x;
  condensation.solve(y, x);
  Vector<double> dx(x);
  dx -= x_ref;
  // The final stress recovery factorises F alone and only solves.
  hrcontact::CellCondensation factor_only;
  factor_only.factorise(F);
  Vector<double> x_alone;
  factor_only.solve(y, x_alone);
  x_alone -= x_ref;

  FullMatrix<double> K_transpose(m, m);
  K_transpose.copy_transposed(K);

  std::cout << n << " x " << m
            << (definite ? ", positive definite" : ", indefinite")
            << ": Cholesky factor taken: "
            << (condensation.positive_definite() ? "yes" : "no")
            << "\n  K_c = B F^-1 B^T as with the inverse (1e-12): "
            << hrcontact_tests::check(relative_difference(K, K_ref), 1e-12)
            // The factor's Y^T Y is symmetric by construction; the
            // inverse's B R to round-off.
            << (definite ? "\n  K_c symmetric (exactly): " :
                           "\n  K_c symmetric (1e-12): ")
            << hrcontact_tests::check(relative_difference(K_transpose, K),
                                      definite ? 0. : 1e-12)
            << "\n  R = F^-1 B^T as with the inverse (1e-12): "
            << hrcontact_tests::check(relative_difference(R, R_ref), 1e-12)
            << "\n  F^-1 y as with the inverse (1e-12): "
            << hrcontact_tests::check(dx.l2_norm() / x_ref.l2_norm(), 1e-12)
            << "\n  F^-1 y with F factorised alone (1e-12): "
            << hrcontact_tests::check(x_alone.l2_norm() / x_ref.l2_norm(),
                                      1e-12)
            << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::mt19937                     random(17);
  compare(12, 8, true, random);
  compare(48, 24, true, random);
  compare(12, 8, false, random);
}
