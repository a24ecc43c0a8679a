// The condensed path's two linear solvers: UMFPACK and CG + Trilinos ML AMG
// (rigid-body modes as near null space; a fresh hierarchy per Newton step
// from a cold start, and a reused hierarchy with warm starts) must give the
// same augmented Lagrangian history: the same alpha sequence, the same
// released set at every multiplier update, and p equal to 1e-8 relative
// (CG stops at a relative residual of 1e-12). Lift-off, Hertz and the
// tunnel lining in 2D, the block on a foundation in 3D (six rigid-body
// modes).

#include <deal.II/base/mpi.h>

#include "tests.h"

template <int dim>
std::unique_ptr<hrcontact::HRProblem<dim>>
run(const std::string &scene,
    const std::string &extra,
    const std::string &solver)
{
  return hrcontact_tests::solve_from_text<dim>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) + "/../parameters/" +
                               scene) +
    extra +
    "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
    "subsection Linear solver\n" +
    solver +
    "end\nsubsection Output\n  set Write solution = false\n"
    "  set Output directory = results\nend\n");
}

template <int dim>
void
compare(const std::string &scene, const std::string &extra)
{
  const auto a = run<dim>(scene, extra, "  set Solver = direct\n");
  std::cout << scene << ": " << (*a->results().contact).history.size()
            << " multiplier updates, "
            << (*a->results().contact).total_newton_steps
            << " Newton steps with UMFPACK" << std::endl;
  for (const std::string variant : {"fresh", "reuse"})
    {
      const bool reuse = (variant == "reuse");
      const auto b =
        run<dim>(scene,
                 extra,
                 std::string(
                   "  set Solver = cg-amg\n  set Reuse preconditioner = ") +
                   (reuse ? "true" : "false") +
                   "\n  set Warm start = " + (reuse ? "true" : "false") + "\n");
      const auto c =
        hrcontact_tests::compare_histories((*a->results().contact),
                                           (*b->results().contact));
      std::cout << "  CG + AMG, "
                << (reuse ? "reused hierarchy, warm start" :
                            "fresh hierarchy, cold start")
                << ": same alpha sequence: " << (c.same_alpha ? "yes" : "NO")
                << ", same released sets: " << (c.same_sets ? "yes" : "NO")
                << ", p to 1e-8: "
                << hrcontact_tests::check(c.p_difference, 1e-8) << std::endl;
    }
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>("lift-off.prm", "");
  compare<2>("hertz.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n");
  compare<2>("tunnel.prm",
             "subsection Geometry\n  set Global refinements = 2\nend\n");
  compare<3>("block-3d-contact.prm",
             "subsection Geometry\n  set Global refinements = 1\nend\n");
}
