// A block pushed into a corner between two frictionless walls
// (parameters/corner.prm, eq. 11): the node in the corner has one
// constraint per wall, and its reaction is the conic combination of the two
// normals. Exact solutions (uniform stress, reproduced by Q1/DGQ1):
//   theta = 60 and 120 degrees, pressure q on the free faces: sigma = -q I,
//   u = -(1 - nu) q / E x, wall pressure q;
//   theta = 90, pressures q_x (right face) and q (top face): sigma =
//   diag(-q_x, -q), u = (eps_xx x, eps_yy y).
// Nodal reactions are then -(wall pressure) x (tributary length): half the
// adjacent edges. Both Newton-step paths.

#include <map>

#include "tests.h"

using namespace hrcontact;

void
run(const double theta, const double q_x, const std::string &path)
{
  const double       q = 1e6, E = 30e9, nu = 0.2;
  std::ostringstream extra;
  extra << "set Constants = L_a = 2, L_b = 1, theta = " << theta
        << ", q = 1e6, E = 30e9, nu = 0.2, q_x = " << q_x << "\n";
  if (theta == 90)
    extra << "subsection Loads\n  set Tractions = 1: -q_x; 0 | 3: 0; -q\nend\n";
  extra << "subsection Equilibrium reduction\n  set Path = " << path
        << "\nend\n"
        << "subsection Output\n  set Write solution = false\n  set Print "
           "timing = false\n  set Output directory = results\nend\n";
  auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/corner.prm") +
    extra.str());
  std::ostringstream quiet;
  problem->output_results(quiet);
  const auto &system = problem->results().system;
  const auto &solver = (*problem->results().contact);

  // Reactions against -(pressure) x (tributary length) on each wall.
  std::map<int, std::vector<std::pair<double, unsigned int>>> walls;
  for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
    {
      const EquilibriumRow &row = system.rows[system.contact_rows[k]];
      const auto           &x   = system.node_coordinates[row.node];
      const int wall            = (row.direction_component(1) < -0.999) ? 0 : 1;
      walls[wall].emplace_back(std::hypot(x[0], x[1]), k);
    }
  double       worst_reaction = 0;
  unsigned int corner_rows    = 0;
  for (auto &[wall, nodes] : walls)
    {
      std::sort(nodes.begin(), nodes.end());
      const double pressure = (wall == 0) ? q : (theta == 90 ? q_x : q);
      for (unsigned int j = 0; j < nodes.size(); ++j)
        {
          const double left = j > 0 ? nodes[j].first - nodes[j - 1].first : 0;
          const double right =
            j + 1 < nodes.size() ? nodes[j + 1].first - nodes[j].first : 0;
          const double exact = -pressure * 0.5 * (left + right);
          worst_reaction =
            std::max(worst_reaction,
                     std::abs(
                       problem->results().reactions.contact[nodes[j].second] -
                       exact) /
                       (pressure * 0.125));
          corner_rows += (nodes[j].first == 0);
        }
    }
  // Displacements against the exact linear field, at every node.
  const double eps_xx = (theta == 90) ? (-q_x + nu * q) / E : -(1 - nu) * q / E;
  const double eps_yy = (theta == 90) ? (-q + nu * q_x) / E : -(1 - nu) * q / E;
  std::vector<bool> seen(system.node_coordinates.size(), false);
  double            worst_u = 0;
  for (const auto &row : system.rows)
    if (!seen[row.node])
      {
        seen[row.node] = true;
        const auto &x  = system.node_coordinates[row.node];
        worst_u        = std::max(
          {worst_u,
                  std::abs(problem->results().displacement[row.combination[0].first] -
                    eps_xx * x[0]),
                  std::abs(problem->results().displacement[row.combination[1].first] -
                    eps_yy * x[1])});
      }
  std::cout << "theta = " << theta << ", " << path << ": converged "
            << (solver.converged() ? "yes" : "NO") << ", " << corner_rows
            << " constraints at the corner node, " << system.contact_rows.size()
            << " in all" << std::endl;
  std::cout << "  reactions match the exact wall pressure "
            << (worst_reaction < 1e-8 ? "to 1e-8" : "NOT") << std::endl;
  std::cout << "  displacements match the exact field "
            << (worst_u < 1e-8 * std::abs(eps_xx) ? "to 1e-8" : "NOT")
            << std::endl;
  std::cout << "  equilibrium imbalance "
            << (std::stod(problem->results().summary.get(
                  "equilibrium_imbalance")) < 1e-10 ?
                  "below 1e-10" :
                  "TOO LARGE")
            << std::endl;
}

// An eccentric load on the top (its right half only) tilts the block: the
// corner node lifts off both walls (two springs along non-orthogonal
// directions on the condensed path) and the iteration has work to do. The
// paths must take the same history and reactions, with the Signorini
// conditions met.
void
run_tilted()
{
  std::vector<std::vector<double>> reactions;
  for (const std::string path : {"null-space", "condensed"})
    {
      auto problem = hrcontact_tests::solve_from_text<2>(
        hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                   "/../parameters/corner.prm") +
        "subsection Loads\n  set Tractions = 3: 0; -q*(x > 1)\nend\n"
        "subsection Equilibrium reduction\n  set Path = " +
        path +
        "\nend\nsubsection Output\n  set Write solution = false\n  set "
        "Print timing = false\n  set Output directory = results\nend\n");
      std::ostringstream quiet;
      problem->output_results(quiet);
      const auto  &solver      = (*problem->results().contact);
      unsigned int corner_open = 0;
      for (unsigned int k = 0; k < solver.released.size(); ++k)
        corner_open +=
          solver.released[k] &&
          problem->results().system.node_coordinates
              [problem->results()
                 .system.rows[problem->results().system.contact_rows[k]]
                 .node][0] == 0 &&
          problem->results().system.node_coordinates
              [problem->results()
                 .system.rows[problem->results().system.contact_rows[k]]
                 .node][1] == 0;
      const double tolerance = solver.tolerance_used;
      std::cout << "tilted, " << path << ": converged "
                << (solver.converged() ? "yes" : "NO") << ", updates "
                << solver.history.size() << ", Newton steps "
                << solver.total_newton_steps << ", pressed "
                << problem->results().summary.get("pressed_constraints")
                << ", corner constraints open " << corner_open << std::endl;
      std::cout << "  no tension beyond the tolerance: "
                << (std::stod(problem->results().summary.get(
                      "max_positive_p_n")) < 10 * tolerance ?
                      "yes" :
                      "NO")
                << ", no penetration: "
                << (std::stod(problem->results().summary.get(
                      "max_penetration")) < 1e-12 ?
                      "yes" :
                      "NO")
                << std::endl;
      reactions.push_back(problem->results().reactions.contact);
    }
  double difference = 0, scale = 0;
  for (unsigned int k = 0; k < reactions[0].size(); ++k)
    {
      difference =
        std::max(difference, std::abs(reactions[0][k] - reactions[1][k]));
      scale = std::max(scale, std::abs(reactions[0][k]));
    }
  std::cout << "  the paths' reactions agree "
            << (difference < 1e-9 * scale ? "to 1e-9" : "NOT") << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string path : {"null-space", "condensed"})
    {
      run(60, 1e6, path);
      run(120, 1e6, path);
      run(90, 2.5e6, path);
    }
  run_tilted();
}
