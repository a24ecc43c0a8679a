// The regularisations and iteration schemes of issue 5 on lift-off (17 base
// nodes) and a small Hertz mesh (192 cells), all on the condensed path:
// consistent AL (eq. 26), Macaulay AL (eq. 27) and the displacement AL of
// eq. 29, each classical and diagonal (section 4.4). Every converged run
// must give the consistent classical reactions to 1e-7 of the largest one,
// with no tension and no penetration beyond 1e-8 (relative). The Macaulay
// AL in the classical scheme must stop with the named cycle error (its kink
// at p = 0 makes the inner Newton return to a solved set), not hang.

#include "tests.h"

std::unique_ptr<hrcontact::HRProblem<2>>
run(const std::string &scene,
    const std::string &regularisation,
    const std::string &scheme)
{
  std::ostringstream text;
  text << hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                     "/../parameters/" + scene + ".prm")
       << (scene == "hertz" ?
             "subsection Geometry\n  set Global refinements = 3\nend\n" :
             "")
       << "subsection Augmented Lagrangian\n"
       << "  set Regularisation = " << regularisation << "\n"
       << "  set Iteration scheme = " << scheme << "\n"
       << "  set Initial penalty scaling = nodal compliance\n"
       << "  set Initial penalty = 1e4\nend\n"
       << "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
       << "subsection Output\n  set Write solution = false\n"
       << "  set Output directory = results\nend\n";
  return hrcontact_tests::solve_from_text<2>(text.str());
}

int
main()
{
  for (const std::string scene : {"lift-off", "hertz"})
    {
      const auto reference =
        run(scene, "consistent augmented Lagrangian", "classical");
      double p_scale = 0, u_scale = 0;
      for (const double p : reference->results().reactions.contact)
        p_scale = std::max(p_scale, std::abs(p));
      for (const double u : reference->results().displacement)
        u_scale = std::max(u_scale, std::abs(u));
      std::cout << scene << ": reference converged: "
                << (reference->results().converged() ? "yes" : "NO")
                << std::endl;
      for (const std::string variant :
           {"consistent", "Macaulay", "displacement"})
        for (const std::string scheme : {"classical", "diagonal"})
          {
            const auto problem =
              run(scene, variant + " augmented Lagrangian", scheme);
            const auto &al      = (*problem->results().contact);
            const auto &sys     = problem->results().system;
            double      p_error = 0, tension = 0, penetration = 0;
            for (unsigned int k = 0; k < sys.contact_rows.size(); ++k)
              {
                const auto &row = sys.rows[sys.contact_rows[k]];
                double      w   = 0;
                for (const auto &[dof, c] : row.combination)
                  w += c * problem->results().displacement[dof];
                const double p = problem->results().reactions.contact[k];
                p_error =
                  std::max(p_error,
                           std::abs(p -
                                    reference->results().reactions.contact[k]));
                tension     = std::max(tension, p);
                penetration = std::max(penetration, w - row.value);
              }
            std::cout << "  " << variant << ", " << scheme << ": ";
            if (al.converged())
              std::cout << "converged in " << al.history.size() << " updates, "
                        << al.total_newton_steps
                        << " Newton steps; reactions as the reference (1e-7): "
                        << hrcontact_tests::check(p_error / p_scale, 1e-7)
                        << "; no tension (1e-8): "
                        << hrcontact_tests::check(tension / p_scale, 1e-8)
                        << "; no penetration (1e-8): "
                        << hrcontact_tests::check(penetration / u_scale, 1e-8);
            else
              std::cout << ((al.outcome ==
                               hrcontact::SolveOutcome::inner_cycle ||
                             al.outcome == hrcontact::SolveOutcome::periodic) ?
                              "stopped: the inner Newton cycles" :
                            (al.outcome == hrcontact::SolveOutcome::diverged) ?
                              "stopped by the divergence guard" :
                              "NOT converged");
            std::cout << std::endl;
          }
    }
}
