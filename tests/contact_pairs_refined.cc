// Contact between two bodies on locally refined meshes: the two cylinders
// (parameters/two-cylinders.prm, 3 refinements) with one side refined by
// hand, and with adaptive cycles.
//
// A box around the contact zone on the lower (master) cylinder only: the
// upper (slave) cylinder's faces opposite are refined to the same level
// (MatchedContactRefinement), the new surface vertices lie on both
// circles, the global balance holds to round-off, and the nodal pressures
// do not oscillate from node to node (unmatched surfaces do, by several
// percent: the master chords' sagitta). Both pair methods. Adaptive cycles
// (traction jump, 2 cycles, mortar): converged, balanced, no oscillation;
// under mpirun the distributed mesh marks the same cells and gives the
// serial peak pressure to 1e-9.

#include <deal.II/base/mpi.h>

#include <hrcontact/adaptivity/adaptive_run.h>

#include <algorithm>
#include <filesystem>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  std::string
  scene(const std::string &method, const std::string &refinement)
  {
    return read_file(std::string(SOURCE_DIR) +
                     "/../parameters/two-cylinders.prm") +
           "subsection Geometry\n  set Global refinements = 3\nend\n"
           "subsection Contact\n  set Pair method = " +
           method +
           "\nend\n"
           "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
           "subsection Mesh refinement\n" +
           refinement +
           "end\n"
           "subsection Output\n  set Print timing = false\n"
           "  set Write solution = false\n";
  }

  /** Surface faces of boundary @p id with x below 0.01: (x from, x to,
   * level), sorted, and the largest distance of their vertices from the
   * circle of radius @p radius about @p centre_y. */
  std::vector<std::array<double, 3>>
  surface(const dealii::Triangulation<2> &tria,
          const unsigned int              id,
          const double                    radius,
          const double                    centre_y,
          double                         &off_circle)
  {
    std::vector<std::array<double, 3>> faces;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == id &&
              face->center()[0] < 0.01)
            {
              double x0 = face->vertex(0)[0], x1 = face->vertex(1)[0];
              faces.push_back(std::array<double, 3>{
                {std::min(x0, x1), std::max(x0, x1), double(cell->level())}});
              for (unsigned int v = 0; v < 2; ++v)
                {
                  const dealii::Point<2> p = face->vertex(v);
                  off_circle =
                    std::max(off_circle,
                             std::abs(std::hypot(p[0], p[1] - centre_y) -
                                      radius));
                }
            }
    std::sort(faces.begin(), faces.end());
    return faces;
  }

  /**
   * The amplitude of a node-to-node oscillation of the pressures, over the
   * peak, from pressure.csv: the largest fourth difference over 16 (an
   * alternating +-e gives e; Hertz's smooth ellipse about 1e-5 at r3's
   * spacing), at the pressed nodes with x < 0.003 = 0.6 a.
   */
  double
  pressure_wiggle(const std::string &file)
  {
    std::istringstream  in(read_file(file));
    std::string         line;
    std::vector<double> p;
    std::getline(in, line);
    while (std::getline(in, line))
      {
        std::istringstream fields(line);
        std::string        x, y, value;
        std::getline(fields, x, ',');
        std::getline(fields, y, ',');
        std::getline(fields, value, ',');
        if (line.find("contact") != std::string::npos && std::stod(x) < 0.003)
          p.push_back(std::stod(value));
      }
    double worst = 0, peak = 0;
    for (unsigned int k = 0; k < p.size(); ++k)
      {
        peak = std::max(peak, std::abs(p[k]));
        if (k >= 2 && k + 2 < p.size())
          worst = std::max(worst,
                           std::abs(p[k - 2] - 4 * p[k - 1] + 6 * p[k] -
                                    4 * p[k + 1] + p[k + 2]) /
                             16);
      }
    return worst / peak;
  }

  void
  box_on_the_master(const std::string &method)
  {
    auto problem = solve_from_text<2>(
      scene(method,
            "  set Refinement region = -0.001, -0.054 : 0.012, -0.0501\n"
            "  set Region refinements = 2\n") +
        "  set Output directory = results-" + method + "\nend\n",
      MPI_COMM_SELF);
    std::ostringstream quiet;
    problem->output_results(quiet);
    const auto &r          = problem->results();
    const auto &s          = r.summary;
    double      off_circle = 0;
    const auto  slave      = surface(r.triangulation(), 2, 0.05, 0, off_circle);
    const auto  master = surface(r.triangulation(), 12, 0.1, -0.15, off_circle);
    // Each slave face against the master faces it overlaps in x.
    bool matched = true;
    int  finest  = 0;
    for (const auto &f : slave)
      for (const auto &g : master)
        if (std::min(f[1], g[1]) - std::max(f[0], g[0]) >
            0.25 * std::min(f[1] - f[0], g[1] - g[0]))
          {
            {
              matched = matched && f[2] == g[2];
            }
            finest = std::max(finest, int(g[2]));
          }
    std::cout
      << std::setprecision(4) << "Two cylinders, " << method
      << ", the lower cylinder refined twice at the contact zone: "
      << s.get("displacement_dofs") << " dofs, converged " << s.get("converged")
      << "\n  the upper cylinder's faces opposite refined to the "
         "same level (finest "
      << finest << "): " << (matched ? "yes" : "NO")
      << "\n  surface vertices on their circles to 1e-12 m: "
      << check(off_circle, 1e-12)
      << "\n  equilibrium imbalance < 1e-10 of the load: "
      << check(s.get_double("equilibrium_imbalance") /
                 std::abs(s.get_double("total_load_y")),
               1e-10)
      << "\n  no node-to-node oscillation of the pressures above 0.5 % of "
         "the peak: "
      << check(pressure_wiggle("results-" + method + "/pressure.csv"), 5e-3)
      << "\n  peak pressure against Hertz: "
      << s.get_double("relative_error_peak_pressure") << std::endl;
  }

  hrcontact::AdaptiveRefinement<2>
  cycles(const MPI_Comm      comm,
         const std::string  &directory,
         hrcontact::Summary &summary)
  {
    dealii::ParameterHandler prm;
    hrcontact::declare_all_parameters(prm);
    prm.parse_input_from_string(scene("mortar",
                                      "  set Adaptive cycles = 2\n"
                                      "  set Estimator = traction jump\n") +
                                "  set Output directory = " + directory +
                                "\nend\n");
    std::ostringstream quiet;
    return hrcontact::run_adaptive_cycles<2>(prm, quiet, comm, &summary);
  }

  void
  adaptive()
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    hrcontact::Summary s;
    const auto         serial =
      cycles(MPI_COMM_SELF, "results-cycles-" + std::to_string(rank), s);
    std::ostringstream out;
    out
      << std::setprecision(4)
      << "Two cylinders, mortar, 2 adaptive cycles (traction jump): dofs "
      << s.get("adaptive_cycle_dofs") << ", converged " << s.get("converged")
      << "\n  equilibrium imbalance < 1e-10 of the load: "
      << check(s.get_double("equilibrium_imbalance") /
                 std::abs(s.get_double("total_load_y")),
               1e-10)
      << "\n  no node-to-node oscillation of the pressures above 0.5 % of the peak: "
      << check(pressure_wiggle("results-cycles-" + std::to_string(rank) +
                               "/pressure.csv"),
               5e-3)
      << "\n  peak pressure against Hertz: "
      << s.get_double("relative_error_peak_pressure") << "\n";
    if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      {
        hrcontact::Summary p;
        const auto         parallel = cycles(MPI_COMM_WORLD, "results", p);
        bool same = parallel.history.size() == serial.history.size();
        for (unsigned int k = 0; same && k < serial.history.size(); ++k)
          same = parallel.history[k].refine == serial.history[k].refine &&
                 parallel.history[k].coarsen == serial.history[k].coarsen;
        out << "  on 2 processes: the same cells marked: "
            << (same ? "yes" : "NO") << ", the same dofs: "
            << (p.get("adaptive_cycle_dofs") == s.get("adaptive_cycle_dofs") ?
                  "yes" :
                  "NO")
            << ", peak pressure agrees to 1e-9: "
            << check(std::abs(p.get_double("peak_pressure") /
                                s.get_double("peak_pressure") -
                              1),
                     1e-9)
            << "\n";
      }
    if (rank == 0)
      std::cout << out.str() << std::flush;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
    {
      box_on_the_master("mortar");
      box_on_the_master("node to segment");
    }
  adaptive();
}
