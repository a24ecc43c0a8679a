// The Pian-Sumihara assumed-stress element (issue 20) against DGQ1, which on
// parallelograms is the Q1 displacement element and shares its locking:
// (a) Cook's membrane (parameters/cooks-membrane.prm, plane stress, E = 1,
//     nu = 1/3): the deflection of the loaded edge's mid-point (48, 52) at
//     2 ... 32 cells per side against the published converged value 23.96;
//     Pian-Sumihara within 0.5 % at 16 cells, 0.1 % at 32, and nearer than
//     DGQ1 at every mesh;
// (b) the same panel nearly incompressible (plane strain, nu = 0.4999):
//     Pian-Sumihara converges (16 and 32 cells per side within 1 %), DGQ1
//     locks (below 90 % of Pian-Sumihara's value even at 32);
// (c) the cantilever of parameters/cantilever.prm with one cell through the
//     depth (10 x 1): Pian-Sumihara's tip deflection within 2 % of the
//     elasticity solution, DGQ1's far off;
// (e) the 3D counterpart (Pian-Tong): the same cantilever as a prism one
//     cell thick and deep (10 x 1 x 1), nu = 0 so that the plane stress
//     solution is exact in 3D: tip deflection within 2 % (DGQ1 far off);
// (d) both Newton-step paths give the same answers with the assumed
//     stresses (null-space and condensed, 1e-10); the dimension of the
//     null-space reduction's self-stress space is printed for both.

#include <hrcontact/postprocess/field_values.h>
#include <hrcontact/solvers/equilibrium_reduction.h>

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  std::string
  cook(const std::string &element,
       const unsigned int refinements,
       const std::string &extra = "")
  {
    return read_file(std::string(SOURCE_DIR) +
                     "/../parameters/cooks-membrane.prm") +
           "subsection Geometry\n  set Grid arguments = 2\n"
           "  set Global refinements = " +
           std::to_string(refinements) +
           "\nend\n"
           "subsection Finite elements\n  set Stress element = " +
           element + "\nend\n" + extra +
           "subsection Output\n  set Write solution = false\n"
           "  set Output directory = results\nend\n";
  }

  /** A cantilever's tip deflection over the exact one; the assumed
   * stresses must be within 2 %. */
  void
  print_tip(const std::string &element, const double ratio)
  {
    std::cout << "  " << element << ": tip deflection / exact = " << ratio
              << (element == "DGQ1" ?
                    "" :
                    ", within 2 %: " + check(std::abs(ratio - 1), 0.02))
              << '\n';
  }

  double
  tip(const hrcontact::HRProblem<2> &problem)
  {
    return hrcontact::point_value<2>(problem.results(),
                                     dealii::Point<2>(48, 52),
                                     "uy");
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(5);
  const std::vector<std::string> elements = {"DGQ1", "Pian-Sumihara"};

  // (a), (b)
  for (const bool incompressible : {false, true})
    {
      const std::string material =
        incompressible ? "subsection Material\n  set Poisson's ratio = "
                         "0.4999\n  set Plane condition = plane strain\nend\n" :
                         "";
      std::cout << "Cook's membrane, "
                << (incompressible ? "plane strain, nu = 0.4999" :
                                     "plane stress, nu = 1/3 (reference 23.96)")
                << "\n  cells per side, deflection at (48, 52) DGQ1, "
                   "Pian-Sumihara\n";
      std::map<std::string, std::vector<double>> value;
      for (unsigned int r = 0; r <= 4; ++r)
        {
          std::cout << "  " << (2 << r);
          for (const auto &element : elements)
            {
              const double v =
                tip(*solve_from_text<2>(cook(element, r, material)));
              value[element].push_back(v);
              std::cout << ", " << v;
            }
          std::cout << '\n';
        }
      const auto &q1 = value["DGQ1"], &ps = value["Pian-Sumihara"];
      if (!incompressible)
        {
          bool nearer = true, within = true;
          for (unsigned int k = 0; k < ps.size(); ++k)
            {
              nearer &= std::abs(ps[k] - 23.96) < std::abs(q1[k] - 23.96);
              if (k >= 3)
                within &= std::abs(ps[k] / 23.96 - 1) < (k == 3 ? 5e-3 : 1e-3);
            }
          std::cout << "  Pian-Sumihara nearer 23.96 at every mesh: "
                    << (nearer ? "yes" : "NO")
                    << ", within 0.5 % at 16 cells and 0.1 % at 32: "
                    << (within ? "yes" : "NO") << '\n';
        }
      else
        std::cout << "  Pian-Sumihara 16 vs 32 cells within 1 %: "
                  << check(std::abs(ps[3] / ps[4] - 1), 0.01)
                  << ", DGQ1 locks (32 cells below 0.9 of Pian-Sumihara): "
                  << check(q1[4] / ps[4], 0.9) << '\n';
    }

  // (c)
  {
    const std::string cantilever =
      read_file(std::string(SOURCE_DIR) + "/../parameters/cantilever.prm");
    std::cout << "Cantilever, 10 x 1 cells (one through the depth)\n";
    for (const auto &element : elements)
      {
        const auto problem = solve_from_text<2>(
          cantilever +
          "subsection Geometry\n  set Global refinements = 0\n"
          "end\nsubsection Finite elements\n"
          "  set Stress element = " +
          element +
          "\nend\nsubsection Output\n  set Write solution = false\n"
          "  set Output directory = results\nend\n");
        const double L = 10, D = 1, I = D * D * D / 12, P = -1e6, E = 210e9,
                     nu    = 0.3;
        const double exact = P * L * L * L / (3 * E * I) +
                             (4 + 5 * nu) * P * L * D * D / (24 * E * I);
        const double v = hrcontact::point_value<2>(problem->results(),
                                                   dealii::Point<2>(L, 0),
                                                   "uy");
        print_tip(element, v / exact);
      }
  }

  // (e)
  {
    std::cout << "Cantilever prism, 10 x 1 x 1 cells, nu = 0\n";
    for (const auto &element : elements)
      {
        const auto problem = solve_from_text<3>(
          "set Dimension = 3\n"
          "set Constants = L = 10, D = 1, I = D^3/12, P = -1e6, E = 210e9\n"
          "subsection Geometry\n"
          "  set Grid generator = subdivided_hyper_rectangle\n"
          "  set Grid arguments = 10, 1, 1 : 0, -0.5, 0 : 10, 0.5, 1 : true\n"
          "end\n"
          "subsection Material\n  set Young's modulus = E\n"
          "  set Poisson's ratio = 0\nend\n"
          "subsection Finite elements\n  set Stress element = " +
          element +
          "\nend\n"
          "subsection Loads\n"
          "  set Tractions = 1: 0; P/(2*I)*(D^2/4 - y^2); 0\nend\n"
          "subsection Supports\n"
          "  set Prescribed displacements = 0: -P*y/(6*E*I)*2*(y^2 - D^2/4); "
          "0; 0\nend\n"
          "subsection Output\n  set Write solution = false\n"
          "  set Output directory = results\nend\n");
        const double L = 10, D = 1, I = D * D * D / 12, P = -1e6, E = 210e9;
        const double exact =
          P * L * L * L / (3 * E * I) + 4 * P * L * D * D / (24 * E * I);
        const double v = hrcontact::point_value<3>(problem->results(),
                                                   dealii::Point<3>(L, 0, 0.5),
                                                   "uy");
        print_tip(element, v / exact);
      }
  }

  // (d)
  {
    std::cout << "Paths, Cook's membrane 8 x 8 cells\n";
    for (const auto &element : elements)
      {
        const auto dense     = solve_from_text<2>(cook(
          element,
          2,
          "subsection Equilibrium reduction\n  set Path = null-space\nend\n"));
        const auto condensed = solve_from_text<2>(cook(
          element,
          2,
          "subsection Equilibrium reduction\n  set Path = condensed\nend\n"));
        std::cout << "  " << element << ": self-stress dimension "
                  << dense->results().solve.reduction->n_self_equilibrated()
                  << ", stresses agree to 1e-10: "
                  << check(relative(dense->results().stress,
                                    condensed->results().stress),
                           1e-10)
                  << ", displacements: "
                  << check(relative(dense->results().displacement,
                                    condensed->results().displacement),
                           1e-10)
                  << '\n';
      }
  }
}
