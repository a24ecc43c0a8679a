// The error bound (issue 52) on a distributed mesh: each process equilibrates
// the vertex patches of its own cells (its ghost layer holds them whole) and
// reconstructs its own cells; the bound and the residuals reduce over the
// processes. parameters/cantilever-error-bound.prm at 640 cells on the
// condensed path (a p4est mesh) on MPI_COMM_WORLD and serially on
// MPI_COMM_SELF: the same bound, true error and effectivity to 1e-9, and the
// reconstruction admissible to 1e-9 on both. Then the same after three
// bound-driven adaptive cycles (hanging nodes: the owner of each coarse cell
// sends its hanging nodes' moments to its ghosts): the same cells, bound
// and effectivity to 1e-9. Then both for the contact scene
// parameters/signorini-error-bound.prm (each process gathers the contact
// faces and shares the reactions alike), and for its two-body form with a
// contact pair, parameters/two-body-signorini-error-bound.prm (a master
// node's row carries its own hanging shares only on a distributed mesh:
// the slave's come with the slave's reaction), and the tied pair of
// parameters/two-body-tied-error-bound.prm.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/adaptivity/adaptive_run.h>

#include "tests.h"

using namespace hrcontact_tests;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto text = [](const std::string &directory, const std::string &scene) {
    std::string t =
      read_file(std::string(SOURCE_DIR) + "/../parameters/" + scene);
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
  const auto compare = [&](const std::string &scene) {
    const auto parallel =
      solve_from_text<2>(text("results", scene), MPI_COMM_WORLD);
    const auto serial =
      solve_from_text<2>(text("results-serial-" + std::to_string(rank), scene),
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
      difference = std::max(difference,
                            std::abs(P.summary.get_double(key) -
                                     S.summary.get_double(key)) /
                              std::abs(S.summary.get_double(key)));
    for (const auto *r : {&P, &S})
      for (const std::string key : {"error_bound_traction_residual",
                                    "error_bound_equilibrium_residual"})
        residual = std::max(residual, r->summary.get_double(key));
    difference = dealii::Utilities::MPI::max(difference, MPI_COMM_WORLD);
    residual   = dealii::Utilities::MPI::max(residual, MPI_COMM_WORLD);
    if (rank == 0)
      std::cout << scene << ": "
                << (distributed ? "distributed" : "serial (WRONG)")
                << " mesh on "
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

    // Bound-driven cycles: meshes with hanging nodes.
    const auto adaptive = [&](const MPI_Comm comm, const std::string &dir) {
      dealii::ParameterHandler prm;
      hrcontact::declare_all_parameters(prm);
      prm.parse_input_from_string(
        read_file(std::string(SOURCE_DIR) + "/../parameters/" + scene) +
        "subsection Mesh refinement\n  set Adaptive cycles = 3\n"
        "  set Estimator = bound\nend\n"
        "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
        "subsection Output\n  set Write solution = false\n"
        "  set Print timing = false\n  set Output directory = " +
        dir + "\nend\n");
      std::ostringstream quiet;
      hrcontact::Summary summary;
      hrcontact::run_adaptive_cycles<2>(prm, quiet, comm, &summary);
      return summary;
    };
    const auto A = adaptive(MPI_COMM_WORLD, "results-adaptive");
    const auto B = adaptive(MPI_COMM_SELF,
                            "results-adaptive-serial-" + std::to_string(rank));
    double     adaptive_difference = 0, adaptive_residual = 0;
    for (const std::string key :
         {"error_bound", "effectivity_index", "cells", "displacement_dofs"})
      adaptive_difference =
        std::max(adaptive_difference,
                 std::abs(A.get_double(key) - B.get_double(key)) /
                   std::abs(B.get_double(key)));
    for (const auto *s : {&A, &B})
      for (const std::string key : {"error_bound_traction_residual",
                                    "error_bound_equilibrium_residual"})
        adaptive_residual = std::max(adaptive_residual, s->get_double(key));
    adaptive_difference =
      dealii::Utilities::MPI::max(adaptive_difference, MPI_COMM_WORLD);
    adaptive_residual =
      dealii::Utilities::MPI::max(adaptive_residual, MPI_COMM_WORLD);
    if (rank == 0)
      std::cout << scene << " after 3 bound-driven cycles (" << A.get("cells")
                << " cells, hanging nodes): cells, dofs, bound and effectivity "
                   "as serially to 1e-9: "
                << check(adaptive_difference, 1e-9)
                << ", admissible to 1e-9 on both: "
                << check(adaptive_residual, 1e-9) << std::endl;
  };
  compare("cantilever-error-bound.prm");
  compare("signorini-error-bound.prm");
  compare("two-body-signorini-error-bound.prm");
  compare("two-body-tied-error-bound.prm");
}
