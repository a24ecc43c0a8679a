// The no-tension cone in closed form at the Gauss points on a distributed
// mesh: each process builds the Newton model of its own and ghost cells'
// points from the strain state it holds (a DGQ1 field like the stresses),
// and the stop and the line search reduce over the processes. The
// manufactured pier (parameters/no-tension-manufactured-pier.prm, 8 x 48
// cells) on MPI_COMM_WORLD (p4est mesh) and serially on MPI_COMM_SELF must
// take the same Newton steps with the same model stress error after each
// (1e-8: 115 semismooth steps carry the round-off of the two partitions
// further than a smooth law's), the same stress error against the closed
// form, fracture strain and cracked fraction (1e-9) and the same base
// reaction (1e-10). The same for the barrier path (Method = interior
// point), and for the shipped arch (parameters/masonry-arch.prm, 192 cells,
// the interior point its default takes): the same steps, the model errors
// step by step to 1e-7 (its line searches carry the partitions' round-off
// to 1.4e-8 on 2 processes), fracture strain, cracked fraction and largest
// contact pressure to 1e-9, the same vertical reaction (1e-10).

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  /** A scene at @p refinements with @p extra, on every process and
   * serially; @p keys are the summary's fields compared to 1e-9, named
   * @p what in the report. */
  void
  compare(const std::string              &scene,
          const unsigned int              refinements,
          const std::string              &extra,
          const std::string              &tag,
          const std::vector<std::string> &keys,
          const std::string              &what,
          const std::string              &history_bound = "1e-8")
  {
    // Each serial run writes its summary into a directory of its own.
    const auto text = [&](const std::string &directory) {
      return read_file(std::string(SOURCE_DIR) + "/../parameters/" + scene +
                       ".prm") +
             extra + "subsection Geometry\n  set Global refinements = " +
             std::to_string(refinements) +
             "\nend\n"
             "subsection Output\n  set Write solution = false\n"
             "  set Output directory = " +
             directory + "\nend\n";
    };
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const auto parallel =
      solve_from_text<2>(text("results" + tag), MPI_COMM_WORLD);
    const auto  serial = solve_from_text<2>(text("results" + tag + "-serial-" +
                                                std::to_string(rank)),
                                           MPI_COMM_SELF);
    const auto &P = parallel->results(), &S = serial->results();
    const bool  distributed =
      dynamic_cast<const dealii::parallel::distributed::Triangulation<2> *>(
        &P.triangulation()) != nullptr;
    double history = history_difference(P.material.changes, S.material.changes);
    std::ostringstream quiet;
    parallel->output_results(quiet);
    serial->output_results(quiet);
    const auto relative = [&](const std::string &key) {
      const double p = P.summary.get_double(key), s = S.summary.get_double(key);
      return std::abs(p - s) / std::max(std::abs(s), 1e-300);
    };
    double fields = 0;
    for (const auto &key : keys)
      fields = std::max(fields, relative(key));
    double reaction = relative("total_reaction_y");
    history         = dealii::Utilities::MPI::max(history, MPI_COMM_WORLD);
    fields          = dealii::Utilities::MPI::max(fields, MPI_COMM_WORLD);
    reaction        = dealii::Utilities::MPI::max(reaction, MPI_COMM_WORLD);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << (distributed ? "distributed" : "serial (WRONG)")
                << " mesh on "
                << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                << " processes, the same Newton steps: "
                << (P.material.newton_steps == S.material.newton_steps ? "yes" :
                                                                         "NO")
                << "\n  model stress errors step by step agree to "
                << history_bound << ": "
                << check(history, std::stod(history_bound)) << "\n  " << what
                << " agree to 1e-9: " << check(fields, 1e-9)
                << "\n  base reactions agree to 1e-10: "
                << check(reaction, 1e-10) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string              pier = "no-tension-manufactured-pier";
  const std::vector<std::string> pier_keys{"stress_error_l2",
                                           "stress_error_max",
                                           "largest_fracture_strain",
                                           "cracked_area_fraction"};
  const std::string              pier_fields =
    "stress errors, fracture strain, cracked fraction";
  compare(pier, 3, "", "", pier_keys, pier_fields);
  // The barrier path (Method = interior point): its stages and line
  // searches reduce over the processes too.
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "Method = interior point:" << std::endl;
  compare(pier,
          3,
          "subsection Stress constraint iteration\n"
          "  set Method = interior point\n  set Stress tolerance = 1e-4\n"
          "end\n",
          "-interior",
          pier_keys,
          pier_fields);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "The masonry arch (masonry-arch.prm, 192 cells):" << std::endl;
  compare("masonry-arch",
          2,
          "",
          "-arch",
          {"largest_fracture_strain", "cracked_area_fraction", "max_abs_p_n"},
          "fracture strain, cracked fraction, largest contact pressure",
          "1e-7");
}
