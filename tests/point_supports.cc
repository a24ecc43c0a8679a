// Supports/Point supports (issue 54's manufactured pier needs it): a block
// [0, 2] x [0, 1] (plane strain) pressed by q on its top onto a frictionless
// foundation, its horizontal rigid motion held at the one base node (1, 0)
// only. The exact answer is homogeneous: sigma_yy = -q, sigma_xx = sigma_xy
// = 0, and the block spreads freely about that node, u_x = (x - 1) eps_xx
// with eps_xx = nu (1 + nu) q / E. Holding u_x = 0 along the whole base
// (the old way) must spoil it. And a point that is not a node of its
// boundary, a wrong value count, an unknown component and a malformed entry
// are refused by name.

#include <hrcontact/postprocess/field_values.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const std::string block = R"(
set Dimension = 2
set Constants = q = 1e6, E = 1e9, nu = 0.3
subsection Geometry
  set Grid generator     = subdivided_hyper_rectangle
  set Grid arguments     = 2, 1 : 0, 0 : 2, 1 : true
  set Global refinements = 3
end
subsection Material
  set Young's modulus = E
  set Poisson's ratio = nu
  set Plane condition = plane strain
end
subsection Loads
  set Tractions = 3: 0; -q
end
subsection Contact
  set Obstacles = 2: 0, 0 : 0, -1
end
subsection Output
  set Write solution = false
  set Output directory = results
end
)";

  // The largest deviation from the exact stresses and u_x, relative to q
  // and to the largest exact u_x.
  std::pair<double, double>
  errors(const hrcontact::Results<2> &r)
  {
    const double q = 1e6, E = 1e9, nu = 0.3, exx = nu * (1 + nu) * q / E;
    double       stress = 0, ux = 0;
    for (const double x : {0.1, 0.55, 1.0, 1.3, 1.95})
      for (const double y : {0.05, 0.5, 0.95})
        {
          const dealii::Point<2> p(x, y);
          stress =
            std::max({stress,
                      std::abs(hrcontact::point_value(r, p, "sxx")) / q,
                      std::abs(hrcontact::point_value(r, p, "syy") + q) / q,
                      std::abs(hrcontact::point_value(r, p, "sxy")) / q});
          ux = std::max(
            ux,
            std::abs(hrcontact::point_value(r, p, "ux") - (x - 1) * exx) / exx);
        }
    return {stress, ux};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(3);
  {
    const auto problem = solve_from_text<2>(
      block + "subsection Supports\n  set Point supports = 2 (1, 0) x: 0\n"
              "end\n");
    const auto [stress, ux] = errors(problem->results());
    std::cout << "held at one node: stresses homogeneous to 1e-10 of q: "
              << check(stress, 1e-10)
              << ", u_x = (x - 1) eps_xx to 1e-9: " << check(ux, 1e-9)
              << std::endl;
  }
  {
    const auto problem = solve_from_text<2>(
      block + "subsection Supports\n  set Prescribed displacements = 2 x: 0\n"
              "end\n");
    const auto [stress, ux] = errors(problem->results());
    std::cout << "held along the whole base: the stresses off by more than "
                 "1 % of q: "
              << (stress > 1e-2 ? "yes" : "NO") << std::endl;
  }
  for (const std::string entry : {"2 (1.01, 0) x: 0",
                                  "2 (1, 0) x: 0; 0",
                                  "2 (1, 0) w: 0",
                                  "2 1, 0 x: 0",
                                  "2 (1) x: 0"})
    try
      {
        solve_from_text<2>(
          block + "subsection Supports\n  set Point supports = " + entry +
          "\nend\n");
        std::cout << "'" << entry << "': NOT refused" << std::endl;
      }
    catch (const hrcontact::InputError &e)
      {
        std::cout << "'" << entry << "': " << e.what() << std::endl;
      }
}
