// The material Newton iteration on both Newton-step paths (issue 18): the
// null-space path (the paper's reduction, the strain terms d_c in its
// linear term b0 and in the displacements of eq. 51) and the condensed
// path (d_c as the load B_c F_c^-1 d_c and the shift of the recovered
// stresses) must take the same iterates: the same number of steps, the same
// stress change after each (both are exact linear solves), and the same
// stresses and displacements at the end, on the Ramberg-Osgood cantilever
// (prescribed clamp, statically indeterminate) and the bending strip.

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  void
  compare(const std::string &name, const std::string &scene)
  {
    auto solve = [&](const std::string &path) {
      return solve_from_text<2>(scene +
                                "subsection Equilibrium reduction\n"
                                "  set Path = " +
                                path +
                                "\nend\n"
                                "subsection Linear solver\n"
                                "  set Solver = direct\nend\n");
    };
    const auto  dense = solve("null-space"), sparse = solve("condensed");
    const auto &a = dense->results(), &b = sparse->results();
    double      history =
      (a.material.changes.size() == b.material.changes.size()) ? 0. : 1.;
    for (unsigned int k = 0; history < 1 && k < a.material.changes.size(); ++k)
      // A change is itself a difference of iterates: compare it against
      // the iterates' size, 1e-12 of which is round-off.
      history =
        std::max(history,
                 std::abs(a.material.changes[k] - b.material.changes[k]));
    std::cout << name << ": paths " << a.solve.path << " and " << b.solve.path
              << ", " << a.material.newton_steps << " and "
              << b.material.newton_steps << " Newton steps\n"
              << "  stress changes step by step agree to 1e-10: "
              << check(history, 1e-10) << "\n  stresses agree to 1e-10: "
              << check(relative(a.stress, b.stress), 1e-10)
              << "\n  displacements agree to 1e-10: "
              << check(relative(a.displacement, b.displacement), 1e-10)
              << std::endl;
  }
} // namespace

int
main()
{
  compare("Ramberg-Osgood cantilever, 10 x 1 cells x 4",
          read_file(std::string(SOURCE_DIR) + "/../parameters/cantilever.prm") +
            "subsection Finite elements\n  set Stress element = DGQ1\nend\n"
            "subsection Material\n  set Model = Ramberg-Osgood\n"
            "  set Ramberg-Osgood coefficient = 3/7\n"
            "  set Ramberg-Osgood reference stress = 40e6\n"
            "  set Ramberg-Osgood exponent = 5\nend\n");
  compare("Ramberg-Osgood strip in pure bending, 40 x 4 cells",
          read_file(std::string(SOURCE_DIR) +
                    "/../parameters/ramberg-osgood-beam.prm") +
            "subsection Geometry\n  set Global refinements = 2\nend\n");
}
