// The bridge span with seismic stops (parameters/bridge-stops.prm), on both
// Newton-step paths and in both iteration schemes: every branch of the
// two-sided stop law is visited, and each device obeys its branch exactly:
//   free:          |p| below the tolerance, g- < w < g+;
//   at a stop:     w = g+ (p in [p0-, 0]) or w = g- (p in [0, p0+]);
//   beyond a stop: p = p0 (constant) or p = p0 - k (w - g) (linear branch).
// The stops carry the seismic load H = a_h gamma L h, and the two paths give
// the same reactions.

#include <hrcontact/constraints/constraint_law.h>

#include <map>

#include "tests.h"

using namespace hrcontact;

std::vector<double>
run(const std::string &title, const std::string &extra)
{
  auto problem = hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/bridge-stops.prm") +
    extra +
    "subsection Output\n  set Write solution = false\n  set Print timing = "
    "false\n  set Output directory = results\nend\n");
  const auto  &solver    = (*problem->results().contact);
  const auto  &system    = problem->results().system;
  const double tolerance = solver.tolerance_used;

  std::map<std::string, unsigned int> count;
  double                              worst_law = 0, sum_x = 0;
  std::vector<double>                 reactions;
  for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
    {
      const EquilibriumRow &row = system.rows[system.contact_rows[k]];
      const auto *stop = dynamic_cast<const TwoSidedStop *>(row.law.get());
      if (!stop)
        continue;
      double w = 0;
      for (const auto &[dof, c] : row.combination)
        w += c * problem->results().displacement[dof];
      const double p = problem->results().reactions.contact[k];
      reactions.push_back(p);
      sum_x += p * row.combination[0].second;
      const unsigned int branch = solver.pieces[k].branch;
      ++count[stop->branch_name(branch)];
      // The violation of the branch's law (a force; w errors times 1e9 N/m).
      double violation = 0;
      switch (branch)
        {
          case TwoSidedStop::free:
            violation =
              std::max(std::abs(p),
                       1e9 *
                         std::max({0., stop->g_minus - w, w - stop->g_plus}));
            break;
          case TwoSidedStop::at_upper_stop:
            violation = std::max(
              {1e9 * std::abs(w - stop->g_plus), p, stop->p0_minus - p});
            break;
          case TwoSidedStop::at_lower_stop:
            violation = std::max(
              {1e9 * std::abs(w - stop->g_minus), -p, p - stop->p0_plus});
            break;
          default:
            violation = std::abs(p - stop->reaction(w));
        }
      worst_law = std::max(worst_law, violation);
    }
  const double H = 0.5 * 25e3 * 30 * 2;
  std::cout << title << ": converged " << (solver.converged() ? "yes" : "NO")
            << ", updates " << solver.history.size() << ", Newton steps "
            << solver.total_newton_steps << std::endl;
  if ((solver.outcome == hrcontact::SolveOutcome::periodic))
    {
      std::cout << "  stopped: the diagonal scheme is periodic" << std::endl;
      return {};
    }
  for (const auto &[name, n] : count)
    std::cout << "  " << n << " on '" << name << "'" << std::endl;
  std::cout << "  every branch visited: " << (count.size() == 5 ? "yes" : "NO")
            << std::endl;
  std::cout << "  worst violation of a branch law "
            << (worst_law < 10 * tolerance ? "below 10 x tolerance" :
                                             "TOO LARGE")
            << std::endl;
  std::cout << "  stop reactions + seismic load H = "
            << (std::abs(sum_x + H) < 1e-8 * H ? "0 to 1e-8 H" : "NOT ZERO")
            << std::endl;
  return reactions;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);
  const auto reference = run("null-space, classical",
                             "subsection Equilibrium reduction\n  set Path = "
                             "null-space\nend\n");
  std::cout << "  reactions p (N/m):";
  for (const double p : reference)
    std::cout << " " << std::round(p);
  std::cout << std::endl;
  for (const auto &[title, extra] :
       {std::pair<std::string, std::string>{
          "condensed, classical",
          "subsection Equilibrium reduction\n  set Path = condensed\nend\n"},
        std::pair<std::string, std::string>{
          "null-space, diagonal, alpha_0 = 1e6 c_h",
          "subsection Equilibrium reduction\n  set Path = null-space\nend\n"
          "subsection Augmented Lagrangian\n  set Iteration scheme = "
          "diagonal\n  set Initial penalty = 1e6\nend\n"},
        std::pair<std::string, std::string>{
          "condensed, diagonal, alpha_0 = 1e6 c_h",
          "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
          "subsection Augmented Lagrangian\n  set Iteration scheme = "
          "diagonal\n  set Initial penalty = 1e6\nend\n"}})
    {
      const auto reactions  = run(title, extra);
      double     difference = 0, scale = 0;
      for (unsigned int i = 0; i < reactions.size(); ++i)
        {
          difference =
            std::max(difference, std::abs(reactions[i] - reference[i]));
          scale = std::max(scale, std::abs(reference[i]));
        }
      std::cout << "  reactions equal the first run's "
                << (difference < 1e-8 * scale ? "to 1e-8" : "NOT") << std::endl;
    }
  // At the scene's alpha_0 = 1e4 c_h the diagonal scheme runs into a cycle
  // of period 6 (its named stop); the classical scheme converges.
  run("null-space, diagonal, alpha_0 = 1e4 c_h",
      "subsection Equilibrium reduction\n  set Path = null-space\nend\n"
      "subsection Augmented Lagrangian\n  set Iteration scheme = "
      "diagonal\nend\n");
}
