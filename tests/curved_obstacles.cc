// A rigid cylinder pressed into an elastic block
// (parameters/cylinder-indentation.prm): a curved obstacle, linearised at
// each node's nearest point on the circle. Checks
//   - the gaps are the distances to the circle, sqrt(x^2 + R^2) - R;
//   - the contact half-width a and the peak pressure p0 against Hertz's
//     rigid cylinder on a half-space, a = sqrt(4 P R / (pi E*)), p0 = 2P /
//     (pi a): a within one cell, p0 within 3 %;
//   - the same circle as a level set gives the same reactions (to 1e-6: its
//     normals come from a finite-difference gradient);
//   - re-linearising between multiplier updates converges and moves P by a
//     second-order amount (u/R is 3e-3 here);
//   - the bad combinations are named input errors.

#include "tests.h"

using namespace hrcontact;

struct Result
{
  double              P = 0, a = 0, p0 = 0, h = 0, worst_gap = 0;
  bool                converged = false;
  unsigned int        updates   = 0;
  std::vector<double> reactions;
};

Result
run(const std::string &contact)
{
  auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/cylinder-indentation.prm") +
    "subsection Contact\n" + contact +
    "end\nsubsection Output\n  set Write solution = false\n  set Print "
    "timing = false\n  set Output directory = results\nend\n");
  const auto &system = problem->results().system;
  const auto &solver = (*problem->results().contact);
  Result      result;
  result.converged = solver.converged();
  result.updates   = solver.history.size();
  result.reactions = problem->results().reactions.contact;
  // Top nodes by x: total force (full model = twice the half), the last
  // node in contact and the first open one, the pressure at the centre.
  std::vector<std::pair<double, unsigned int>> nodes;
  for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
    {
      const EquilibriumRow &row = system.rows[system.contact_rows[k]];
      const double          x   = system.node_coordinates[row.node][0];
      nodes.emplace_back(x, k);
      result.P -= 2 * problem->results().reactions.contact[k] *
                  row.direction_component(1);
      result.worst_gap =
        std::max(result.worst_gap,
                 std::abs(row.value - (std::sqrt(x * x + 1.) - 1.)));
    }
  std::sort(nodes.begin(), nodes.end());
  result.h = nodes[1].first - nodes[0].first;
  for (unsigned int j = 0; j + 1 < nodes.size(); ++j)
    if (!solver.released[nodes[j].second] &&
        solver.released[nodes[j + 1].second])
      result.a = 0.5 * (nodes[j].first + nodes[j + 1].first);
  result.p0 =
    -problem->results().reactions.contact[nodes[0].second] / (0.5 * result.h);
  return result;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double E = 1e9, nu = 0.3, R = 1, E_star = E / (1 - nu * nu);

  const Result circle = run("  set Curved obstacles = 3: circle : 0, R : R\n"
                            "  set Update curved obstacles = false\n");
  const double a_hertz =
    std::sqrt(4 * circle.P * R / (dealii::numbers::PI * E_star));
  const double p0_hertz = 2 * circle.P / (dealii::numbers::PI * a_hertz);
  std::cout << "circle: converged " << (circle.converged ? "yes" : "NO")
            << ", updates " << circle.updates << std::endl;
  std::cout << "  gaps = distance to the circle "
            << (circle.worst_gap < 1e-12 ? "to 1e-12" : "NOT") << std::endl;
  std::cout << "  P = " << std::setprecision(6) << circle.P
            << " N/m; a = " << circle.a << " m against Hertz " << a_hertz
            << " m: "
            << (std::abs(circle.a - a_hertz) <= circle.h ?
                  "within one cell" :
                  "OFF BY MORE THAN A CELL")
            << std::endl;
  std::cout << "  p0 = " << circle.p0 << " Pa against Hertz " << p0_hertz
            << " Pa: "
            << (std::abs(circle.p0 / p0_hertz - 1) < 0.03 ?
                  "within 3 %" :
                  "OFF BY MORE THAN 3 %")
            << std::endl;

  auto compare = [](const Result &a, const Result &b) {
    double difference = 0, scale = 0;
    for (unsigned int k = 0; k < a.reactions.size(); ++k)
      {
        difference =
          std::max(difference, std::abs(a.reactions[k] - b.reactions[k]));
        scale = std::max(scale, std::abs(a.reactions[k]));
      }
    return difference / scale;
  };
  const Result level_set =
    run("  set Curved obstacles = 3: level set : sqrt(x^2 + (y - R)^2) - R\n"
        "  set Update curved obstacles = false\n");
  std::cout << "level set of the same circle: converged "
            << (level_set.converged ? "yes" : "NO") << ", reactions equal "
            << (compare(circle, level_set) < 1e-6 ? "to 1e-6" : "NOT")
            << std::endl;

  const Result updated = run("  set Curved obstacles = 3: circle : 0, R : R\n"
                             "  set Update curved obstacles = true\n");
  std::cout << "circle, re-linearised after every update: converged "
            << (updated.converged ? "yes" : "NO") << ", updates "
            << updated.updates << ", P changes by " << std::setprecision(2)
            << std::abs(updated.P / circle.P - 1) << ", "
            << (std::abs(updated.P / circle.P - 1) < 1e-3 ? "less than 1e-3" :
                                                            "MORE THAN 1e-3")
            << std::endl;
  const Result updated_level_set =
    run("  set Curved obstacles = 3: level set : sqrt(x^2 + (y - R)^2) - R\n"
        "  set Update curved obstacles = true\n");
  std::cout << "level set, re-linearised: converged "
            << (updated_level_set.converged ? "yes" : "NO")
            << ", reactions equal the circle's "
            << (compare(updated, updated_level_set) < 1e-6 ? "to 1e-6" : "NOT")
            << std::endl;

  for (const std::string &bad :
       {std::string("  set Curved obstacles = 3: circle : 0, R : R\n  set "
                    "Update curved obstacles = true\nend\nsubsection "
                    "Equilibrium reduction\n  set Path = null-space\n"),
        std::string("  set Curved obstacles = 3: sphere : 0, R, 0 : R\n"),
        std::string("  set Curved obstacles = 3: circle : 0, R : R\nend\n"
                    "subsection Equilibrium reduction\n  set Path = "
                    "null-space\n"),
        std::string("  set Curved obstacles = 3: circle : 0, R : -1\n"),
        std::string("  set Curved obstacles = 3: ellipse : 0, R : R\n")})
    try
      {
        run(bad);
        std::cout << "accepted: WRONG" << std::endl;
      }
    catch (const InputError &e)
      {
        std::cout << "error: " << e.what() << std::endl;
      }
}
