// The contact fields of solution.vtu (ContactFields) on the Hertz scene
// (parameters/hertz.prm, condensed path): at every contact node the nodal
// contact_pressure equals -p over half the two neighbouring chords,
// computed here independently from the rows sorted along the surface; the
// contact_gap is 0 at pressed nodes and g - w_n > 0 at open ones; the
// contact_status is 2 at pressed and 1 at open nodes; the peak of the field
// is within 5 % of Hertz's p0. Serially and on 2 processes (each checks the
// nodes it owns). Then pressure.csv and pressure.png of write_pressure_plot.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/postprocess/contact_fields.h>
#include <hrcontact/postprocess/pressure_plot.h>

#include <filesystem>
#include <map>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  /** What the rows say at a contact node, independently of ContactFields. */
  struct Expected
  {
    dealii::Point<2> x;
    double           pressure = 0, gap = 0;
    bool             pressed = false;
  };

  std::vector<Expected>
  expected_nodes(const hrcontact::Results<2> &r)
  {
    std::vector<Expected> nodes;
    for (unsigned int k = 0; k < r.system.contact_rows.size(); ++k)
      {
        const auto &row = r.system.rows[r.system.contact_rows[k]];
        const auto &c   = r.system.node_coordinates[row.node];
        Expected    e;
        e.x        = dealii::Point<2>(c[0], c[1]);
        e.pressure = r.reactions.contact[k]; // divided below
        e.gap      = row.value - r.reactions.contact_w[k];
        e.pressed  = !r.contact->released[k];
        nodes.push_back(e);
      }
    std::sort(nodes.begin(), nodes.end(), [](const auto &a, const auto &b) {
      return a.x[0] < b.x[0];
    });
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const double left = j > 0 ? nodes[j].x.distance(nodes[j - 1].x) : 0.;
        const double right =
          j + 1 < nodes.size() ? nodes[j].x.distance(nodes[j + 1].x) : 0.;
        nodes[j].pressure = -nodes[j].pressure / (0.5 * (left + right));
      }
    return nodes;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm    = MPI_COMM_WORLD;
  const auto                               problem = solve_from_text<2>(
    condensed_scene(
      "hertz.prm",
      "subsection Postprocess\n  set Pressure plot = false\nend\n"),
    comm);
  const hrcontact::Results<2>      &r = problem->results();
  const hrcontact::ContactFields<2> fields(r);
  const std::vector<Expected>       nodes = expected_nodes(r);
  const double                      R = 0.05, E = 210e9, nu = 0.3;
  const double                      Es = E / (1 - nu * nu), a = 0.1 * R,
               P  = dealii::numbers::PI * Es * a * a / (4 * R),
               p0 = 2 * P / (dealii::numbers::PI * a);

  double pressure_error = 0, pressed_gap = 0, open_gap_error = 0, peak = 0;
  unsigned int      checked = 0, status_wrong = 0, open_not_positive = 0;
  const auto       &dofs = fields.get_dof_handler();
  std::vector<bool> seen(dofs.n_dofs(), false);
  for (const auto &cell : dofs.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto v : cell->vertex_indices())
        {
          const auto i = cell->vertex_dof_index(v, 0);
          if (seen[i] || !dofs.locally_owned_dofs().is_element(i))
            continue;
          seen[i] = true;
          peak    = std::max(peak, fields.get_pressure()(i));
          for (const Expected &e : nodes)
            if (e.x.distance(cell->vertex(v)) < 1e-12 * R)
              {
                ++checked;
                pressure_error =
                  std::max(pressure_error,
                           std::abs(fields.get_pressure()(i) - e.pressure));
                status_wrong += fields.get_status()(i) != (e.pressed ? 2. : 1.);
                if (e.pressed)
                  pressed_gap =
                    std::max(pressed_gap, std::abs(fields.get_gap()(i)));
                else
                  {
                    open_not_positive += !(fields.get_gap()(i) > 0);
                    open_gap_error =
                      std::max(open_gap_error,
                               std::abs(fields.get_gap()(i) - e.gap));
                  }
              }
        }
  using dealii::Utilities::MPI::max;
  using dealii::Utilities::MPI::sum;
  checked           = sum(checked, comm);
  status_wrong      = sum(status_wrong, comm);
  open_not_positive = sum(open_not_positive, comm);
  pressure_error    = max(pressure_error, comm) / p0;
  pressed_gap       = max(pressed_gap, comm) / R;
  open_gap_error    = max(open_gap_error, comm) / R;
  peak              = max(peak, comm);
  if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      unsigned int pressed = 0;
      for (const Expected &e : nodes)
        pressed += e.pressed;
      std::cout << "Hertz, " << r.triangulation().n_global_active_cells()
                << " cells on " << dealii::Utilities::MPI::n_mpi_processes(comm)
                << " process(es), "
                << (dynamic_cast<
                      const dealii::parallel::distributed::Triangulation<2> *>(
                      &r.triangulation()) ?
                      "distributed" :
                      "serial")
                << " mesh: " << nodes.size() << " contact nodes, " << pressed
                << " pressed\n"
                << "  every contact node checked once: "
                << (checked == nodes.size() ? "yes" : "NO") << "\n"
                << "  contact_pressure = -p / tributary chord (1e-12 p0): "
                << check(pressure_error, 1e-12) << "\n"
                << "  contact_gap 0 where pressed (1e-12 R): "
                << check(pressed_gap, 1e-12) << "\n"
                << "  contact_gap = g - w_n > 0 where open (1e-12 R): "
                << check(open_gap_error, 1e-12)
                << ", positive: " << (open_not_positive == 0 ? "yes" : "NO")
                << "\n"
                << "  contact_status 2 pressed, 1 open: "
                << (status_wrong == 0 ? "yes" : "NO") << "\n"
                << "  peak of contact_pressure within 5 % of Hertz's p0: "
                << check(std::abs(peak - p0) / p0, 0.05) << std::endl;

      // The picture: the table holds Hertz's ellipse beside each node.
      std::vector<hrcontact::PressurePoint> profile;
      for (const Expected &e : nodes)
        profile.push_back({e.x[0], e.x[1], e.pressure, e.pressed});
      hrcontact::HertzEllipse hertz;
      hertz.half_width = a;
      hertz.peak       = p0;
      std::filesystem::remove_all("plot");
      std::filesystem::create_directories("plot");
      std::ostringstream log;
      const auto         files = hrcontact::write_pressure_plot(
        profile, hertz, "plot", MPI_COMM_SELF, log);
      std::ifstream in("plot/pressure.csv");
      std::string   line;
      std::getline(in, line);
      double largest = 0;
      for (const Expected &e : nodes)
        {
          std::getline(in, line);
          const double h = std::stod(line.substr(line.rfind(',') + 1));
          largest = std::max(largest, std::abs(h - hertz.pressure(e.x[0])));
        }
      std::cout << "pressure.csv: Hertz's column is p0 sqrt(1 - x^2/a^2): "
                << check(largest / p0, 1e-10) << "\nfiles:";
      for (const auto &f : files)
        std::cout << " " << f
                  << (std::filesystem::exists("plot/" + f) ? "" : " (MISSING)");
      std::cout << "\nno temporary file left: "
                << (std::filesystem::exists("plot/pressure.png.tmp") ? "NO" :
                                                                       "yes")
                << std::endl;
    }
}
