// Output/Compare with a displacement code (issue 18): the Ramberg-Osgood
// law solved once more the way a displacement code must, Newton on the Q1
// displacements with the law inverted at every Gauss point
// (DisplacementLawStiffness). With DGQ1 stresses and the 2 x 2 Gauss rule
// the stationarity of each cell's stresses makes the law's strain equal
// eps(u) at every Gauss point, so the two codes solve the same discrete
// problem on any quadrilateral or hexahedron: their displacements must
// agree to the iterations' tolerance (1e-9 here; a wrong inversion or a
// wrong strain would show), and the displacement code's Newton steps must
// converge quadratically (a wrong tangent would take many more than 8).
// A linear law is refused by name.

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const std::string compare = "subsection Output\n"
                              "  set Compare with a displacement code = true\n"
                              "end\n";

  template <int dim>
  void
  report(const std::string &name, const std::string &text)
  {
    const auto  problem = solve_from_text<dim>(text + compare);
    const auto &r       = problem->results();
    std::cout << name << ": stress code " << r.material.newton_steps
              << " Newton steps, displacement code "
              << r.diagnostics.displacement_code_steps
              << " (<= 8: " << check(r.diagnostics.displacement_code_steps, 8)
              << "), at most " << r.diagnostics.displacement_code_local_steps
              << " local steps a Gauss point; displacements agree to 1e-9: "
              << check(r.diagnostics.displacement_code_difference, 1e-9)
              << std::endl;
  }
} // namespace

int
main()
{
  const std::string beam = read_file(std::string(SOURCE_DIR) +
                                     "/../parameters/ramberg-osgood-beam.prm");
  for (unsigned int r = 1; r <= 2; ++r)
    report<2>("beam in pure bending, " + std::to_string(1u << r) +
                " cells across",
              beam + "subsection Geometry\n  set Global refinements = " +
                std::to_string(r) + "\nend\n");

  // A cantilever under an end shear load (load-driven), distorted mesh.
  const std::string law = "subsection Material\n"
                          "  set Model = Ramberg-Osgood\n"
                          "  set Young's modulus = 210e9\n"
                          "  set Poisson's ratio = 0.3\n"
                          "  set Ramberg-Osgood coefficient = 3/7\n"
                          "  set Ramberg-Osgood reference stress = 40e6\n"
                          "  set Ramberg-Osgood exponent = 5\n";
  report<2>("cantilever, distorted mesh",
            "set Dimension = 2\n"
            "subsection Geometry\n"
            "  set Grid generator = subdivided_hyper_rectangle\n"
            "  set Grid arguments = 10, 1 : 0, -0.5 : 10, 0.5 : true\n"
            "  set Global refinements = 2\n"
            "  set Distortion = 0.25\n"
            "end\n" +
              law +
              "  set Plane condition = plane stress\n"
              "end\n"
              "subsection Loads\n"
              "  set Tractions = 1: 0; -1.5e6*(0.25 - y^2)\n"
              "end\n"
              "subsection Supports\n"
              "  set Prescribed displacements = 0: 0; 0\n"
              "end\n"
              "subsection Equilibrium reduction\n"
              "  set Path = condensed\n"
              "end\n");
  report<3>("3D cantilever, distorted mesh",
            "set Dimension = 3\n"
            "subsection Geometry\n"
            "  set Grid generator = subdivided_hyper_rectangle\n"
            "  set Grid arguments = 6, 1, 1 : 0, -0.5, -0.5 : 6, 0.5, 0.5 : "
            "true\n"
            "  set Global refinements = 1\n"
            "  set Distortion = 0.2\n"
            "end\n" +
              law +
              "end\n"
              "subsection Loads\n"
              "  set Tractions = 1: 0; -2e6; 0\n"
              "end\n"
              "subsection Supports\n"
              "  set Prescribed displacements = 0: 0; 0; 0\n"
              "end\n"
              "subsection Equilibrium reduction\n"
              "  set Path = condensed\n"
              "end\n");

  // A linear law has nothing to compare.
  try
    {
      solve_from_text<2>(beam +
                         "subsection Material\n  set Model = linear "
                         "elasticity\nend\n" +
                         compare);
      std::cout << "linear law: accepted (wrong)" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cout << "linear law: " << e.what() << std::endl;
    }
}
