#ifndef hrcontact_condensed_mumps_factor_h
#define hrcontact_condensed_mumps_factor_h

#include <deal.II/base/mpi.h>

#include <memory>
#include <vector>

class Epetra_CrsMatrix;
class Epetra_MultiVector;

namespace hrcontact
{
  /**
   * MUMPS (Amestoy et al.) on a distributed symmetric positive definite
   * Epetra matrix, called through its C interface: the one place where
   * hrcontact talks to a solver library without deal.II or Trilinos in
   * between, because Amesos_Mumps always declares the matrix unsymmetric
   * (MUMPS SYM = 0, Trilinos bugs 2331 and 2332), which costs twice the
   * factorisation's operations and memory of the LDL^T that an SPD matrix
   * allows (SYM = 1).
   *
   * Each process passes the upper triangle of its own rows (distributed
   * assembled input, ICNTL(18) = 3); the right-hand side and the solution
   * are gathered on the first process (centralised, ICNTL(20) = ICNTL(21)
   * = 0). The symbolic analysis is done once for the pattern the matrix
   * has at the first factorise(); each later factorise() refills the values
   * and factorises numerically on it.
   */
  class MumpsFactor
  {
  public:
    explicit MumpsFactor(const MPI_Comm communicator);
    ~MumpsFactor();
    MumpsFactor(const MumpsFactor &) = delete;
    MumpsFactor &
    operator=(const MumpsFactor &) = delete;

    /** Factorise @p matrix (its pattern that of the first call); false if
     * MUMPS finds it singular or fails. */
    bool
    factorise(const Epetra_CrsMatrix &matrix);

    /** x = K^{-1} b with the last factors; false if MUMPS fails. */
    bool
    solve(const Epetra_MultiVector &b, Epetra_MultiVector &x);

    /** MUMPS's INFOG(1) after the last call: negative when it failed, -10
     * for a numerically singular matrix (MUMPS' user guide lists the
     * others). */
    int
    error() const;

  private:
    /** Calls MUMPS with job @p job; whether every process succeeded. */
    bool
    call(const int job);

    struct Instance;
    std::unique_ptr<Instance> instance;
    MPI_Comm                  communicator;
    bool                      analysed = false;
    /** This process's entries of the upper triangle: 1-based global rows
     * and columns, their values, and which of the local rows' entries
     * (row after row) they are. */
    std::vector<int>    rows, columns;
    std::vector<double> values;
    std::vector<bool>   kept;
    /** The global rows of each process (on the first process), and this
     * process's; for the gather and scatter of b and x. */
    std::vector<int>    own_rows, all_rows, counts, offsets;
    std::vector<double> full;
  };
} // namespace hrcontact

#endif
