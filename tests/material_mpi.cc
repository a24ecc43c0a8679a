// The material Newton iteration on a distributed mesh (mpirun -np 2): each
// process refreshes F_c and d_c for its own and ghost cells from the
// stresses it holds, and the stopping test reduces over the processes. The
// Ramberg-Osgood strip in pure bending (parameters/ramberg-osgood-beam.prm)
// solved on MPI_COMM_WORLD (condensed path, p4est mesh) and on every
// process serially on MPI_COMM_SELF must take the same Newton steps with
// the same stress change after each (1e-9) and give the same end moment,
// from the support reactions, to 1e-10, with CG + AMG and with MUMPS /
// UMFPACK.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  /** The moment of the reactions at x = 1 about y = 0 (replicated). */
  double
  end_moment(const hrcontact::Results<2> &res)
  {
    double moment = 0;
    for (unsigned int k = 0; k < res.system.prescribed_rows.size(); ++k)
      {
        const auto &row = res.system.rows[res.system.prescribed_rows[k]];
        const auto &x   = res.system.node_coordinates[row.node];
        if (std::abs(x[0] - 1) < 1e-12 && row.combination[0].second == 1)
          moment += res.reactions.support[k] * x[1];
      }
    return moment;
  }

  void
  compare(const std::string &solver)
  {
    const std::string text =
      read_file(std::string(SOURCE_DIR) +
                "/../parameters/ramberg-osgood-beam.prm") +
      "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
      "subsection Linear solver\n  set Solver = " +
      solver +
      "\n  set Tolerance = 1e-13\nend\n"
      "subsection Output\n  set Write solution = false\nend\n";
    const auto  parallel = solve_from_text<2>(text, MPI_COMM_WORLD);
    const auto  serial   = solve_from_text<2>(text, MPI_COMM_SELF);
    const auto &P = parallel->results(), &S = serial->results();
    const bool  distributed =
      dynamic_cast<const dealii::parallel::distributed::Triangulation<2> *>(
        &P.triangulation()) != nullptr;
    double history = history_difference(P.material.changes, S.material.changes);
    const double moment_difference =
      std::abs(end_moment(P) - end_moment(S)) / std::abs(end_moment(S));
    // Every process compares its own run: the worst of them counts.
    history = dealii::Utilities::MPI::max(history, MPI_COMM_WORLD);
    const double moment =
      dealii::Utilities::MPI::max(moment_difference, MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << "Solver = " << solver << ": "
                << (distributed ? "distributed" : "serial (WRONG)")
                << " mesh on "
                << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                << " processes, " << P.material.newton_steps << " and "
                << S.material.newton_steps << " Newton steps\n"
                << "  stress changes step by step agree to 1e-9: "
                << check(history, 1e-9)
                << "\n  end moments agree to 1e-10: " << check(moment, 1e-10)
                << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare("cg-amg");
  compare("direct");
}
