// Initial penalty at the extremes of its range, as factors of the nodal
// compliance c_h (1e-12, 1e-3, 1 and 1e12 x c_h) on the lift-off scene.
// Expected: the first three converge to the same reactions as the default
// 1e4 x c_h (to 1e-7 of the largest reaction); 1e12 x c_h, where the released
// springs no longer hold the block, stops (the solves lose their digits and
// the inner Newton cycles between released sets, or the divergence guard
// trips) with finite reactions, never NaN.

#include "tests.h"

std::unique_ptr<hrcontact::HRProblem<2>>
run(const double factor)
{
  std::ostringstream text;
  text << hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                     "/../parameters/lift-off.prm")
       << "subsection Augmented Lagrangian\n  set Initial penalty = " << factor
       << "\n  set Initial penalty scaling = nodal compliance\nend\n"
       << "subsection Output\n  set Write solution = false\n"
       << "  set Output directory = results\nend\n";
  return hrcontact_tests::solve_from_text<2>(text.str());
}

int
main()
{
  const auto reference = run(1e4);
  double     p_scale   = 0;
  for (const double p : reference->results().reactions.contact)
    p_scale = std::max(p_scale, std::abs(p));
  for (const double factor : {1e-12, 1e-3, 1., 1e12})
    {
      const auto &problem = run(factor);
      const auto &al      = (*problem->results().contact);
      double      p_error = 0;
      bool        finite  = true;
      for (unsigned int k = 0; k < problem->results().reactions.contact.size();
           ++k)
        {
          finite &= std::isfinite(problem->results().reactions.contact[k]);
          p_error =
            std::max(p_error,
                     std::abs(problem->results().reactions.contact[k] -
                              reference->results().reactions.contact[k]));
        }
      std::cout << "alpha_0 = " << factor << " x c_h: "
                << (al.converged() ? "converged" :
                    (al.outcome == hrcontact::SolveOutcome::diverged) ?
                                     "stopped by the divergence guard" :
                    (al.outcome == hrcontact::SolveOutcome::inner_cycle ||
                     al.outcome == hrcontact::SolveOutcome::periodic) ?
                                     "stopped: the inner Newton cycles" :
                                     "NOT converged")
                << " after " << al.history.size()
                << " updates; reactions finite: " << (finite ? "yes" : "NO");
      if (factor < 1e6)
        std::cout << "; converged with the reference reactions (1e-7): "
                  << (al.converged() ?
                        hrcontact_tests::check(p_error / p_scale, 1e-7) :
                        std::string("NO"));
      else
        std::cout << "; stopped, not converged: "
                  << (((al.outcome == hrcontact::SolveOutcome::diverged) ||
                       (al.outcome == hrcontact::SolveOutcome::inner_cycle ||
                        al.outcome == hrcontact::SolveOutcome::periodic)) &&
                          !al.converged() ?
                        "yes" :
                        "NO");
      std::cout << std::endl;
    }
}
