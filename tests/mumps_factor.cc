// MumpsFactor, the direct solver on several processes (MUMPS called as a
// symmetric positive definite LDL^T), against exact solutions: the 1D
// Laplacian with Dirichlet ends (tridiagonal 2, -1, SPD), its rows spread
// over the processes, b = K x for a known x; the same pattern with other
// values, factorised on the first analysis; and the Neumann Laplacian
// (singular) with a right-hand side outside its range, which must not be
// solved silently: either MUMPS refuses it or the solution leaves a
// residual the caller (TrilinosMumps) refuses.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hrcontact/solvers/condensed/mumps_factor.h>

#include <cmath>

#include "tests.h"

using namespace dealii;
using namespace hrcontact_tests;

namespace
{
  void
  fill(TrilinosWrappers::SparseMatrix &K,
       const IndexSet                 &owned,
       const unsigned int              n,
       const double                    end_diagonal,
       const double                    shift)
  {
    K = 0.;
    for (const auto i : owned)
      {
        const bool end = (i == 0 || i + 1 == n);
        K.set(i, i, (end ? end_diagonal : 2.) + shift);
        if (i > 0)
          K.set(i, i - 1, -1.);
        if (i + 1 < n)
          K.set(i, i + 1, -1.);
      }
    K.compress(VectorOperation::insert);
  }

  /** max |x - x_exact| after solving K x = K x_exact; -1 if refused. */
  double
  solve_error(hrcontact::MumpsFactor               &factor,
              const TrilinosWrappers::SparseMatrix &K,
              const IndexSet                       &owned,
              const MPI_Comm                        comm,
              const double                          inconsistency,
              double                               &residual)
  {
    TrilinosWrappers::MPI::Vector exact(owned, comm), b(owned, comm),
      x(owned, comm), r(owned, comm);
    for (const auto i : owned)
      exact(i) = std::sin(0.1 * i) + 1;
    exact.compress(VectorOperation::insert);
    K.vmult(b, exact);
    b.add(inconsistency);
    if (!factor.factorise(K.trilinos_matrix()) ||
        !factor.solve(b.trilinos_vector(), x.trilinos_vector()))
      return -1;
    K.vmult(r, x);
    r -= b;
    residual = r.l2_norm() / b.l2_norm();
    x -= exact;
    return x.linfty_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int               n    = 1000;
  const unsigned int               np   = Utilities::MPI::n_mpi_processes(comm),
                     rank = Utilities::MPI::this_mpi_process(comm);
  IndexSet owned(n);
  owned.add_range(rank * n / np, (rank + 1) * n / np);
  DynamicSparsityPattern dsp(n, n, owned);
  for (const auto i : owned)
    for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1); ++j)
      dsp.add(i, j);
  TrilinosWrappers::SparseMatrix K;
  K.reinit(owned, owned, dsp, comm);

  hrcontact::MumpsFactor factor(comm);
  double                 residual = 0;
  fill(K, owned, n, 2., 0.);
  const double e1 = solve_error(factor, K, owned, comm, 0., residual);
  fill(K, owned, n, 2., 0.5);
  const double e2 = solve_error(factor, K, owned, comm, 0., residual);
  fill(K, owned, n, 1., 0.);
  // b with a part outside the range (its sum is not zero): no x solves it.
  const double e3 = solve_error(factor, K, owned, comm, 1., residual);
  if (rank == 0)
    std::cout << "Dirichlet Laplacian, " << n << " rows on " << np
              << " processes: max error of x below 1e-9 (its condition "
                 "number is 4e5): "
              << check(e1 >= 0 ? e1 : 1., 1e-9)
              << "\nthe same pattern, other values (the first analysis "
                 "kept): max error below 1e-12: "
              << check(e2 >= 0 ? e2 : 1., 1e-12)
              << "\nNeumann Laplacian (singular): refused by MUMPS ("
              << factor.error() << ") or left with a residual above 1e-8: "
              << ((e3 < 0 || residual > 1e-8) ? "yes" : "NO") << std::endl;
}
