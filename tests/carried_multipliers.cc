// After a carried start (Nested iteration), the Newton steps that switch
// rows also give the rows that keep their branch the multiplier update of
// eq. 48 (Augmented Lagrangian/Update carried multipliers with each Newton
// step). That changes how the fine level gets to its answer, not the answer:
// Hertz at 7 refinements (CG + AMG, three coarser levels) with and without
// it gives the same Q-row reactions and displacements to 1e-8, both stop
// with ||pbar|| below their tolerance, and with it the fine level needs
// fewer linear solves (its two edge rows switch in two Newton steps, which
// now also settle the carried multipliers: no update solve of its own).

#include <deal.II/base/mpi.h>

#include "tests.h"

using namespace dealii;

std::unique_ptr<hrcontact::HRProblem<2>>
run_hertz(const bool update)
{
  return hrcontact_tests::solve_from_text<2>(hrcontact_tests::condensed_scene(
    "hertz.prm",
    std::string("subsection Geometry\n  set Global refinements = 7\nend\n"
                "subsection Linear solver\n  set Solver = cg-amg\nend\n"
                "subsection Augmented Lagrangian\n"
                "  set Update carried multipliers with each Newton step = ") +
      (update ? "true" : "false") + "\nend\n"));
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const auto  updated = run_hertz(true), fixed = run_hertz(false);
  const auto &a = updated->results(), &b = fixed->results();
  const auto  differences = hrcontact_tests::answer_differences(a, b);
  std::cout << "Hertz, 7 refinements, CG + AMG, " << a.coarse_levels.size()
            << " coarser levels: converged: " << (a.converged() ? "yes" : "NO")
            << " and " << (b.converged() ? "yes" : "NO")
            << "\n  final ||pbar|| / tolerance <= 1: "
            << hrcontact_tests::check(a.contact->final_norm_pbar /
                                        a.contact->tolerance_used,
                                      1)
            << " and "
            << hrcontact_tests::check(b.contact->final_norm_pbar /
                                        b.contact->tolerance_used,
                                      1)
            << "\n  Q-row reactions agree to 1e-8: "
            << hrcontact_tests::check(differences[0], 1e-8)
            << "\n  displacements agree to 1e-8: "
            << hrcontact_tests::check(differences[1], 1e-8)
            << "\n  fine level: " << a.contact->history.size()
            << " multiplier updates and " << a.solve.linear_statistics.solves
            << " linear solves with the update, " << b.contact->history.size()
            << " and " << b.solve.linear_statistics.solves
            << " without: fewer solves: "
            << (a.solve.linear_statistics.solves <
                    b.solve.linear_statistics.solves ?
                  "yes" :
                  "NO")
            << std::endl;
}
