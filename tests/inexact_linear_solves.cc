// CG leaves noise in the reactions p = Q s - q that the constraint laws
// compare. Too loose a Linear solver/Tolerance used to end the run (an inner
// Newton cycle, an inner iteration at its step limit, or alpha grown on
// noise until the body floated); Hertz refinement 10 (6.3M dofs) hit the
// first at the default 1e-12. Each symptom now tightens CG and goes on: the
// run must converge to the answer of the direct solver (the step limit is
// lowered to 15 so that the third symptom costs little), and at the default
// tolerance nothing is tightened. The AMG aggregates follow the matrix
// graph: with coordinate aggregation (the default on this stretched mesh)
// CG at 1e-8 is accurate enough that nothing needs tightening, and the
// mechanism would go untested. For the same reason these runs start from
// the trial solution (Nested iteration/Coarse levels = 0): from a coarser
// level's displacements and state nothing is tightened down to 1e-5. At 1e-9
// and 1e-8 nothing is tightened either since warm-started solves resolve
// their change to Warm start reduction. A run
// that tightened ends at 1e-2 of its tolerance per tightening (the count is
// printed), one that did not at its own; either agrees with UMFPACK.

#include <deal.II/base/mpi.h>

#include <cmath>

#include "tests.h"

std::unique_ptr<hrcontact::HRProblem<2>>
run(const std::string &solver)
{
  return hrcontact_tests::solve_from_text<2>(
    hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                               "/../parameters/hertz.prm") +
    "subsection Geometry\n  set Global refinements = 6\nend\n"
    "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
    "subsection Augmented Lagrangian\n  set Maximum Newton steps = 15\nend\n"
    "subsection Linear solver\n" +
    solver +
    "end\nsubsection Output\n  set Write solution = false\n"
    "  set Output directory = results\nend\n");
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto  direct = run("  set Solver = direct\n");
  const auto &p_ref  = direct->results().contact->p;
  double      p_max  = 0;
  for (const double v : p_ref)
    p_max = std::max(p_max, std::abs(v));
  std::cout << "Hertz refinement 6, "
            << direct->results().system.n_displacement_dofs
            << " displacement dofs; UMFPACK converged: "
            << (direct->results().converged() ? "yes" : "NO") << std::endl;
  for (const std::string tolerance : {"1e-12", "1e-9", "1e-8", "1e-7"})
    {
      const auto cg =
        run("  set Solver = cg-amg\n  set AMG aggregation = matrix\n"
            "  set Tolerance = " +
            tolerance +
            "\nend\nsubsection Nested iteration\n"
            "  set Coarse levels = 0\n");
      const auto &r          = cg->results();
      const auto &p          = r.contact->p;
      double      difference = 0;
      for (unsigned int i = 0; i < p.size(); ++i)
        difference = std::max(difference, std::abs(p[i] - p_ref[i]));
      std::cout
        << "CG + AMG at Tolerance = " << tolerance
        << ": converged: " << (r.converged() ? "yes" : "NO") << ", tightened: "
        << (r.solve.linear_statistics.tightenings > 0 ? "yes" : "no")
        << ", final tolerance "
        << (r.solve.linear_statistics.tightenings > 0 ?
              "= Tolerance x 1e-2 per tightening (" +
                std::to_string(r.solve.linear_statistics.tightenings) +
                " tightenings): " +
                hrcontact_tests::check(
                  std::abs(
                    r.solve.linear_statistics.tolerance /
                      (std::stod(tolerance) *
                       std::pow(1e-2, r.solve.linear_statistics.tightenings)) -
                    1),
                  1e-12) :
              std::string("as set: ") +
                (r.solve.linear_statistics.tolerance == std::stod(tolerance) ?
                   "yes" :
                   "NO"))
        << ", p as UMFPACK to 1e-7: "
        << hrcontact_tests::check(difference / p_max, 1e-7) << std::endl;
    }
  // The default CG + AMG (coordinate aggregation, 1e-12) started from the
  // last step's displacements and from zero: the same p; a step that keeps
  // the held rows and springs keeps the AMG hierarchy; the warm start saves
  // CG iterations.
  double iterations_per_solve[2] = {0, 0};
  for (const bool warm : {true, false})
    {
      const auto cg =
        run(std::string("  set Solver = cg-amg\n") +
            "  set Warm start = " + (warm ? "true" : "false") + "\n");
      const auto &r          = cg->results();
      const auto &p          = r.contact->p;
      const auto &statistics = r.solve.linear_statistics;
      double      difference = 0;
      for (unsigned int i = 0; i < p.size(); ++i)
        difference = std::max(difference, std::abs(p[i] - p_ref[i]));
      iterations_per_solve[warm ? 0 : 1] =
        double(statistics.iterations) / statistics.solves;
      std::cout << "CG + AMG, default settings, warm start "
                << (warm ? "true" : "false")
                << ": converged: " << (r.converged() ? "yes" : "NO") << ", "
                << statistics.solves << " solves, "
                << statistics.preconditioner_setups
                << " AMG set-ups, p as UMFPACK to 1e-8: "
                << hrcontact_tests::check(difference / p_max, 1e-8)
                << std::endl;
    }
  std::cout << "CG iterations per solve, warm start / from zero <= 0.85: "
            << hrcontact_tests::check(iterations_per_solve[0] /
                                        iterations_per_solve[1],
                                      0.85)
            << std::endl;
}
