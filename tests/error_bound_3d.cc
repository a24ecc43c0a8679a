// The guaranteed error bound in 3D (issue 52; HexahedronFaceTractions,
// HexahedronEquilibration): parameters/cube-error-bound.prm, a manufactured
// cubic displacement on a box with its linear body force and quadratic
// tractions, held at u = 0 on one face.
// - At 2, 16 and 128 cells (serially): effectivity in [1, 2], the
//   Prager-Synge identity |u - u_h|^2 + |sigma - tau|^2 = eta^2 to 1e-10
//   (it holds only if tau is statically admissible), tau admissible to
//   1e-10, the bound halving with h.
// - The displacement perturbed by a smooth field that keeps the support:
//   the bound grows and stays above the perturbed field's true error.
// - On 2 processes (a p4est mesh): the bound, true error and effectivity
//   as serially to 1e-9.
// - What the 3D bound does not cover yet (cells that are not
//   parallelepipeds; contact; bound-driven cycles, which make hanging
//   nodes) is refused by name.
// - A prescribed displacement Q1 cannot meet between the nodes is reported
//   (error_bound_support_mismatch) and warned about.

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q1.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/adaptivity/adaptive_run.h>
#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/core/input.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  std::string
  cube(const unsigned int refinements, const std::string &directory)
  {
    std::string text = scene_at_refinement("cube-error-bound", 2, refinements);
    return text + "subsection Output\n  set Output directory = " + directory +
           "\nend\n";
  }

  std::string
  reference_stress()
  {
    const std::string scene = read_file(std::string(SOURCE_DIR) +
                                        "/../parameters/cube-error-bound.prm");
    const std::string key   = "set Reference stress = ";
    const auto        at    = scene.find(key) + key.size();
    return scene.substr(at, scene.find('\n', at) - at);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string  serial_dir = "results-serial-" + std::to_string(rank);
  std::ostringstream quiet;

  // Three meshes, serially.
  std::vector<double> bounds;
  for (const unsigned int r : {0u, 1u, 2u})
    {
      const auto problem =
        solve_from_text<3>(cube(r, serial_dir), MPI_COMM_SELF);
      problem->output_results(quiet);
      const auto  &s   = problem->results().summary;
      const double eff = s.get_double("effectivity_index");
      bounds.push_back(s.get_double("error_bound"));
      if (rank == 0)
        std::cout
          << "cube r" << r << ": cells " << s.get("cells")
          << ", effectivity in [1, 2]: "
          << (eff >= 1 && eff <= 2 ? "yes" : "NO") << " ("
          << std::setprecision(3) << eff << "), identity to 1e-10: "
          << check(s.get_double("hypercircle_defect"), 1e-10)
          << ", tau admissible to 1e-10: "
          << check(std::max(s.get_double("error_bound_traction_residual"),
                            s.get_double("error_bound_equilibrium_residual")),
                   1e-10)
          << std::endl;
    }
  if (rank == 0)
    for (unsigned int i = 1; i < bounds.size(); ++i)
      std::cout << "  bound ratio to the previous mesh in [1.8, 2.2]: "
                << (bounds[i - 1] / bounds[i] >= 1.8 &&
                        bounds[i - 1] / bounds[i] <= 2.2 ?
                      "yes" :
                      "NO")
                << std::endl;

  // A support Q1 cannot meet between the nodes (u_y = 1e-3 y^2 z on x = 0,
  // where the exact u is 0: the data then belong to another problem): u_h
  // is not kinematically admissible, and summary.txt says so.
  {
    std::string       text = cube(1, serial_dir);
    const std::string from = "set Prescribed displacements = 0: 0; 0; 0";
    text.replace(text.find(from),
                 from.size(),
                 "set Prescribed displacements = 0: 0; 1e-3*y^2*z; 0");
    const auto         bad = solve_from_text<3>(text, MPI_COMM_SELF);
    std::ostringstream bad_log;
    bad->output_results(bad_log);
    const auto good = solve_from_text<3>(cube(1, serial_dir), MPI_COMM_SELF);
    good->output_results(quiet);
    const double m_bad = bad->results().summary.get_double(
                   "error_bound_support_mismatch"),
                 m_good = good->results().summary.get_double(
                   "error_bound_support_mismatch");
    if (rank == 0)
      std::cout << "support mismatch reported: u = 0 held: "
                << check(m_good, 1e-14)
                << ", u_y = 1e-3 y^2 z held: " << (m_bad > 1e-3 ? "yes" : "NO")
                << " (above 1e-3), warned: "
                << (bad_log.str().find("misses the prescribed displacements") !=
                        std::string::npos ?
                      "yes" :
                      "NO")
                << std::endl;
  }

  // The displacement perturbed by 5 % of its largest value times a smooth
  // field that vanishes on the held face x = 0: still kinematically
  // admissible, so eta(v) >= |u - v|_E.
  {
    const auto problem = solve_from_text<3>(cube(1, serial_dir), MPI_COMM_SELF);
    auto       perturbed(problem->results());
    const auto &dh = perturbed.spaces.dof_handler_displacement;
    std::vector<dealii::Point<3>> support(dh.n_dofs());
    dealii::DoFTools::map_dofs_to_support_points(
      dealii::StaticMappingQ1<3>::mapping, dh, support);
    const double umax = perturbed.displacement.linfty_norm();
    for (unsigned int i = 0; i < support.size(); ++i)
      perturbed.displacement(i) += 0.05 * umax * support[i][0] *
                                   std::sin(2 * support[i][1] + support[i][2]);
    hrcontact::EquilibratedStress<3> exact(problem->results()),
      shifted(perturbed);
    exact.compute();
    shifted.compute();
    const auto reference = hrcontact::make_function<3>(
      reference_stress(), 6, problem->results().scene.constants, "test");
    const double e =
      std::sqrt(shifted.compare(*reference).displacement_error_squared);
    if (rank == 0)
      std::cout << "perturbed displacement: still admissible to 1e-10: "
                << check(std::max(shifted.traction_residual,
                                  shifted.cell_residual),
                         1e-10)
                << ", the bound grows: "
                << (shifted.bound() > exact.bound() ? "yes" : "NO")
                << ", stays above the true error: "
                << (shifted.bound() >= e ? "yes" : "NO") << std::endl;
  }

  // Distributed against serial, at 128 cells.
  {
    const std::string condensed =
      "subsection Equilibrium reduction\n  set Path = condensed\nend\n";
    const auto parallel =
      solve_from_text<3>(cube(2, "results") + condensed, MPI_COMM_WORLD);
    const auto serial =
      solve_from_text<3>(cube(2, serial_dir) + condensed, MPI_COMM_SELF);
    parallel->output_results(quiet);
    serial->output_results(quiet);
    const auto &P = parallel->results(), &S = serial->results();
    const bool  distributed =
      dynamic_cast<const dealii::parallel::distributed::Triangulation<3> *>(
        &P.triangulation()) != nullptr;
    double difference = 0;
    for (const std::string key :
         {"error_bound", "energy_error", "effectivity_index"})
      difference = std::max(difference,
                            std::abs(P.summary.get_double(key) -
                                     S.summary.get_double(key)) /
                              std::abs(S.summary.get_double(key)));
    difference = dealii::Utilities::MPI::max(difference, MPI_COMM_WORLD);
    if (rank == 0)
      std::cout << "cube r2 on "
                << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                << " processes ("
                << (distributed ? "distributed" : "serial (WRONG)")
                << " mesh): bound, true error and effectivity as serially to "
                   "1e-9: "
                << check(difference, 1e-9) << ", admissible to 1e-10: "
                << check(std::max(P.summary.get_double(
                                    "error_bound_traction_residual"),
                                  P.summary.get_double(
                                    "error_bound_equilibrium_residual")),
                         1e-10)
                << std::endl;
  }

  // Not covered yet: distorted cells (every process runs it; rank 0
  // prints).
  {
    std::ostringstream out;
    std::streambuf    *old = std::cout.rdbuf(out.rdbuf());
    print_input_refusal<3>(
      "distorted cells",
      cube(1, "results") +
        "subsection Geometry\n  set Distortion = 0.2\nend\n");
    std::cout.rdbuf(old);
    if (rank == 0)
      std::cout << out.str();
  }
  // Contact in 3D: a contact pair (parameters/stacked-boxes-3d.prm; the 2D
  // check of the pair rows must not read 3D rows).
  {
    std::ostringstream out;
    std::streambuf    *old = std::cout.rdbuf(out.rdbuf());
    print_input_refusal<3>(
      "contact pair in 3D",
      read_file(std::string(SOURCE_DIR) +
                "/../parameters/stacked-boxes-3d.prm") +
        "subsection Postprocess\n  set Error bound = true\nend\n"
        "subsection Output\n  set Write solution = false\n"
        "  set Output directory = results\nend\n");
    std::cout.rdbuf(old);
    if (rank == 0)
      std::cout << out.str();
  }
  // Bound-driven cycles would make hanging nodes: refused before a solve.
  {
    dealii::ParameterHandler prm;
    hrcontact::declare_all_parameters(prm);
    prm.parse_input_from_string(
      cube(1, "results") +
      "subsection Mesh refinement\n  set Estimator = bound\n"
      "  set Adaptive cycles = 2\nend\n");
    std::ostringstream log;
    try
      {
        hrcontact::run_adaptive_cycles<3>(prm, log, MPI_COMM_WORLD);
        if (rank == 0)
          std::cout << "bound-driven cycles in 3D: NOT refused" << std::endl;
      }
    catch (const hrcontact::InputError &e)
      {
        if (rank == 0)
          std::cout << "bound-driven cycles in 3D: refused before a solve: "
                    << (log.str().find("adaptive cycle 0") ==
                            std::string::npos ?
                          "yes" :
                          "NO")
                    << ": " << e.what() << std::endl;
      }
  }
}
