// Output/Time the Q1 floor: the benchmarks' floor is a plain Q1
// displacement solve of the same mesh and supports, its stiffness assembled
// from the displacement bilinear form (not from the HR blocks) and solved by
// CG with the same ML AMG. On rectangular and box grids HR with DGQ1
// stresses equals Q1 (tests/hr_equals_q1), so the floor's displacements
// must equal the run's own: plane strain with a bilateral normal support
// (block), plane stress (cantilever), 3D (block-3d). The summary reports the
// floor's time, CG iterations and the ratio to the solve.

#include <deal.II/base/mpi.h>

#include "tests.h"

void
compare(const std::string &scene, const unsigned int dim)
{
  const std::string text =
    hrcontact_tests::read_file(std::string(SOURCE_DIR) + "/../parameters/" +
                               scene + ".prm") +
    // The floor is the HR solution only with DGQ1 stresses (the cantilever
    // scene takes Pian-Sumihara).
    "subsection Finite elements\n  set Stress element = DGQ1\nend\n"
    "subsection Output\n  set Time the Q1 floor = true\n"
    "  set Write solution = false\n  set Output directory = results\nend\n";
  auto report = [&](const auto &results) {
    hrcontact::FieldVector d = results.diagnostics.floor_displacement;
    d -= results.displacement;
    const auto &s = results.summary;
    std::cout << scene << " (" << s.get("cells") << " cells, "
              << s.get("plane_condition") << ", " << s.get("solution_path")
              << " path):\n  floor displacements equal the HR solution "
                 "(1e-8 relative): "
              << hrcontact_tests::check(d.linfty_norm() /
                                          results.displacement.linfty_norm(),
                                        1e-8)
              << "\n  summary has the floor: CG iterations > 0: "
              << (s.get_double("q1_floor_cg_iterations") > 0 ? "yes" : "NO")
              << ", ratio contact_solve_to_floor > 0: "
              << (s.get_double("contact_solve_to_floor") > 0 ? "yes" : "NO")
              << std::endl;
  };
  std::ostringstream quiet;
  if (dim == 2)
    {
      auto problem = hrcontact_tests::solve_from_text<2>(text);
      problem->output_results(quiet);
      report(problem->results());
    }
  else
    {
      auto problem = hrcontact_tests::solve_from_text<3>(text);
      problem->output_results(quiet);
      report(problem->results());
    }
}

int
main(int argc, char **argv)
{
  // Trilinos (the floor's CG + AMG) needs MPI.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare("block", 2);
  compare("cantilever", 2);
  compare("block-3d", 3);
}
