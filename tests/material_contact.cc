// A nonlinear material with unilateral contact (issue 18): each material
// Newton step is a whole augmented Lagrangian solve, started from the last
// step's multipliers. (1) A Ramberg-Osgood block pressed by its top's
// displacement onto a rigid plane presses every base node, so it must give
// the block on a bilateral frictionless support (Supports/Normal
// displacements) to the contact iteration's tolerance: stresses to 1e-8.
// (2) The lift-off scene with a Ramberg-Osgood body, the loaded corner well
// past sigma_0: the KKT conditions at the end (compressive reactions, no
// penetration, complementarity, equilibrium), and the same answer on the
// null-space path (stresses to 1e-8), which stops at its round-off floor
// (MaterialIteration::stopped_at_roundoff).

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const std::string ramberg_osgood =
    "subsection Material\n"
    "  set Model = Ramberg-Osgood\n"
    "  set Plane condition = plane stress\n"
    "  set Ramberg-Osgood coefficient = 3/7\n"
    "  set Ramberg-Osgood reference stress = %s\n"
    "  set Ramberg-Osgood exponent = 5\n"
    "end\n"
    "subsection Output\n  set Write solution = false\n"
    "  set Print timing = false\n  set Output directory = results\nend\n";

  std::string
  law(const std::string &sigma_0)
  {
    std::string text = ramberg_osgood;
    text.replace(text.find("%s"), 2, sigma_0);
    return text;
  }

  std::string
  describe(const hrcontact::Results<2> &r)
  {
    std::ostringstream s;
    s << r.material.newton_steps
      << " Newton steps, last stress change < 1e-10: "
      << check(r.material.changes.empty() ? 1. : r.material.changes.back(),
               1e-10)
      << ", converged " << (r.converged() ? "yes" : "NO");
    return s.str();
  }

  // The dense null-space path stops at its round-off floor (about 1e-9 of
  // the largest stress with these stiff contact rows), which depends on the
  // BLAS: only bounds are printed.
  std::string
  describe_dense(const hrcontact::Results<2> &r)
  {
    std::ostringstream s;
    s << "at most 12 Newton steps: "
      << (r.material.newton_steps <= 12 ? "yes" : "NO")
      << ", last stress change < 1e-8: "
      << check(r.material.changes.empty() ? 1. : r.material.changes.back(),
               1e-8)
      << ", converged " << (r.converged() ? "yes" : "NO");
    return s.str();
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  const std::string block =
    read_file(std::string(SOURCE_DIR) + "/../parameters/block.prm") +
    law("15e6");
  const auto bilateral = solve_from_text<2>(block);
  const auto unilateral =
    solve_from_text<2>(block + "subsection Supports\n"
                               "  set Normal displacements =\nend\n"
                               "subsection Contact\n"
                               "  set Obstacles = 2: 0, 0 : 0, -1\nend\n");
  std::cout << "Pressed block, bilateral support: "
            << describe(bilateral->results())
            << "\n  on a rigid plane: " << describe(unilateral->results())
            << "\n  the same stresses to 1e-8: "
            << check(relative(unilateral->results().stress,
                              bilateral->results().stress),
                     1e-8)
            << std::endl;

  const std::string lift_off =
    read_file(std::string(SOURCE_DIR) + "/../parameters/lift-off.prm") +
    law("0.5e6");
  const auto condensed = solve_from_text<2>(
    lift_off + "subsection Equilibrium reduction\n  set Path = condensed\n"
               "end\n");
  const auto dense = solve_from_text<2>(
    lift_off + "subsection Equilibrium reduction\n  set Path = null-space\n"
               "end\n");
  std::ostringstream quiet;
  condensed->output_results(quiet); // the balance report for print_kkt
  std::cout << "Lift-off, Ramberg-Osgood body, condensed path: "
            << describe(condensed->results()) << '\n';
  print_kkt(*condensed);
  std::cout << "  null-space path: " << describe_dense(dense->results())
            << "\n  the same stresses to 1e-8: "
            << check(relative(dense->results().stress,
                              condensed->results().stress),
                     1e-8)
            << std::endl;
}
