// The error bound (issue 52) on a distributed mesh: each process equilibrates
// the vertex patches of its own cells (its ghost layer holds them whole) and
// reconstructs its own cells; the bound and the residuals reduce over the
// processes. parameters/cantilever-error-bound.prm at 640 cells on the
// condensed path (a p4est mesh) on MPI_COMM_WORLD and serially on
// MPI_COMM_SELF: the same bound, true error and effectivity to 1e-9, and the
// reconstruction admissible to 1e-9 on both.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include "tests.h"

using namespace hrcontact_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto text = [](const std::string &directory) {
    std::string       t    = read_file(std::string(SOURCE_DIR) +
                              "/../parameters/cantilever-error-bound.prm");
    const std::string from = "set Global refinements = 2";
    t.replace(t.find(from), from.size(), "set Global refinements = 3");
    return t +
           "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
           "subsection Output\n  set Write solution = false\n"
           "  set Output directory = " +
           directory + "\nend\n";
  };
  const unsigned int rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const auto parallel = solve_from_text<2>(text("results"), MPI_COMM_WORLD);
  const auto serial =
    solve_from_text<2>(text("results-serial-" + std::to_string(rank)),
                       MPI_COMM_SELF);
  std::ostringstream quiet;
  parallel->output_results(quiet);
  serial->output_results(quiet);
  const auto &P = parallel->results(), &S = serial->results();
  const bool  distributed =
    dynamic_cast<const dealii::parallel::distributed::Triangulation<2> *>(
      &P.triangulation()) != nullptr;
  double difference = 0, residual = 0;
  for (const std::string key :
       {"error_bound", "energy_error", "effectivity_index"})
    difference =
      std::max(difference,
               std::abs(P.summary.get_double(key) - S.summary.get_double(key)) /
                 std::abs(S.summary.get_double(key)));
  for (const auto *r : {&P, &S})
    for (const std::string key :
         {"error_bound_traction_residual", "error_bound_equilibrium_residual"})
      residual = std::max(residual, r->summary.get_double(key));
  difference = dealii::Utilities::MPI::max(difference, MPI_COMM_WORLD);
  residual   = dealii::Utilities::MPI::max(residual, MPI_COMM_WORLD);
  if (rank == 0)
    std::cout << (distributed ? "distributed" : "serial (WRONG)") << " mesh on "
              << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
              << " processes: bound, true error and effectivity as serially "
                 "to 1e-9: "
              << check(difference, 1e-9)
              << ", admissible to 1e-9 on both: " << check(residual, 1e-9)
              << ", effectivity in [1, 2]: "
              << (P.summary.get_double("effectivity_index") >= 1 &&
                      P.summary.get_double("effectivity_index") <= 2 ?
                    "yes" :
                    "NO")
              << std::endl;
}
