// Adaptive cycles (Mesh refinement/Adaptive cycles) on Hertz, 3 refinements
// and 3 cycles, with each estimator: every cycle refines (more dofs), the
// estimate falls, the last cycle's contact iteration converges and the
// global balance holds to round-off on its locally refined mesh, and
// solution.vtu carries the refinement_indicator. Under mpirun the same
// cycles run on the distributed mesh and serially on each process: the same
// cells marked in every cycle (by CellId), the same dofs, and the same peak
// pressure and half width to 1e-9. Every cycle after the first starts
// from the previous cycle's contact state (Carry state) and needs at most
// three linear solves; every cycle from the start (Carry state = false)
// gives the same answer to the tolerance. The contact residual estimator
// runs with Doerfler marking (Marking = fixed fraction).

#include <deal.II/base/mpi.h>

#include <hrcontact/adaptivity/adaptive_run.h>

#include <filesystem>

#include "tests.h"

using namespace hrcontact_tests;

hrcontact::AdaptiveRefinement<2>
cycles(const std::string  &settings,
       const MPI_Comm      comm,
       const std::string  &directory,
       hrcontact::Summary &summary)
{
  dealii::ParameterHandler prm;
  hrcontact::declare_all_parameters(prm);
  prm.parse_input_from_string(
    read_file(std::string(SOURCE_DIR) + "/../parameters/hertz.prm") +
    "subsection Geometry\n  set Global refinements = 3\nend\n"
    "subsection Mesh refinement\n  set Adaptive cycles = 3\n"
    "  set Estimator = " +
    settings +
    "\nend\n"
    "subsection Postprocess\n  set Pressure plot = false\nend\n"
    "subsection Output\n  set Print timing = false\n"
    "  set Output directory = " +
    directory + "\nend\n");
  std::ostringstream quiet;
  return hrcontact::run_adaptive_cycles<2>(prm, quiet, comm, &summary);
}

void
run(const std::string &estimator, const std::string &marking = "fixed number")
{
  const std::string  settings = estimator + "\n  set Marking = " + marking;
  const unsigned int rank =
                       dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD),
                     n_processes =
                       dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const std::string  serial_dir = "results-serial-" + std::to_string(rank);
  hrcontact::Summary s;
  const auto         serial = cycles(settings, MPI_COMM_SELF, serial_dir, s);
  std::ostringstream out;
  out << std::setprecision(4) << "Hertz, estimator " << estimator
      << ", marking " << marking << "\n";
  bool        growing = true, falling = true, carried = true;
  const auto &c = serial.cycles;
  for (unsigned int k = 0; k < c.size(); ++k)
    {
      out << "  cycle " << k << ": " << c[k].cells << " cells, "
          << c[k].displacement_dofs << " dofs, estimate " << c[k].estimate
          << "\n";
      if (k > 0)
        {
          growing =
            growing && c[k].displacement_dofs > c[k - 1].displacement_dofs;
          falling = falling && c[k].estimate < c[k - 1].estimate;
          carried = carried && c[k].carried_start && c[k].linear_solves <= 3;
        }
    }
  const std::string vtu = read_file(serial_dir + "/solution.vtu");
  out << "  every cycle adds dofs: " << (growing ? "yes" : "NO")
      << ", the estimate falls every cycle: " << (falling ? "yes" : "NO")
      << "\n  every later cycle starts from the carried state, <= 3 linear "
         "solves: "
      << (carried ? "yes" : "NO")
      << "\n  last cycle converged: " << s.get("converged")
      << ", equilibrium imbalance < 1e-10 of the load: "
      << check(s.get_double("equilibrium_imbalance") /
                 std::abs(s.get_double("total_load_y")),
               1e-10)
      << "\n  peak pressure error "
      << s.get_double("relative_error_peak_pressure") << ", half width error "
      << s.get_double("relative_error_half_width")
      << "\n  summary lists the cycles: " << s.get("adaptive_cycle_dofs")
      << "\n  solution.vtu has the refinement_indicator: "
      << (vtu.find("refinement_indicator") != std::string::npos ? "yes" : "NO")
      << "\n";
  {
    hrcontact::Summary f;
    cycles(settings + "\n  set Carry state = false",
           MPI_COMM_SELF,
           serial_dir + "-from-start",
           f);
    auto relative = [&](const std::string &key) {
      return std::abs(f.get_double(key) - s.get_double(key)) /
             std::abs(s.get_double(key));
    };
    out << "  every cycle from the start: peak pressure agrees to 1e-8: "
        << check(relative("peak_pressure"), 1e-8)
        << ", half width: " << check(relative("contact_half_width"), 1e-8)
        << "\n";
  }
  if (n_processes > 1)
    {
      hrcontact::Summary p;
      const auto parallel   = cycles(settings, MPI_COMM_WORLD, "results", p);
      bool       same_marks = parallel.history.size() == serial.history.size();
      for (unsigned int k = 0; same_marks && k < serial.history.size(); ++k)
        same_marks = parallel.history[k].refine == serial.history[k].refine &&
                     parallel.history[k].coarsen == serial.history[k].coarsen;
      bool same_dofs = true;
      for (unsigned int k = 0; k < serial.cycles.size(); ++k)
        same_dofs = same_dofs && parallel.cycles[k].displacement_dofs ==
                                   serial.cycles[k].displacement_dofs;
      auto relative = [&](const std::string &key) {
        return std::abs(p.get_double(key) - s.get_double(key)) /
               std::abs(s.get_double(key));
      };
      out << "  on " << n_processes
          << " processes: the same cells marked in every cycle: "
          << (same_marks ? "yes" : "NO")
          << ", the same dofs: " << (same_dofs ? "yes" : "NO")
          << "\n  peak pressure agrees to 1e-9: "
          << check(relative("peak_pressure"), 1e-9) << ", half width to 1e-9: "
          << check(relative("contact_half_width"), 1e-9) << "\n";
    }
  if (rank == 0)
    std::cout << out.str() << std::flush;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run("kelly");
  run("traction jump");
  run("contact residual", "fixed fraction");
}
