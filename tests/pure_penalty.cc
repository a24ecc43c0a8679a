// The pure quadratic penalty (Regularisation = pure penalty): no multiplier
// updates, alpha fixed. On the lift-off scene it ends with one exact solve of
// its quadratic piece; released constraints carry a spurious tension of
// about (opening) / alpha. Checked: the tension falls in proportion to
// 1/alpha (factor 100 per factor 100 in alpha, to 5 %), and the reactions
// approach the consistent augmented Lagrangian's, whose tension is zero.

#include "tests.h"

std::unique_ptr<hrcontact::HRProblem<2>>
run(const std::string &regularisation, const double factor)
{
  std::ostringstream text;
  text << hrcontact_tests::read_file(std::string(SOURCE_DIR) +
                                     "/../parameters/lift-off.prm")
       << "subsection Augmented Lagrangian\n  set Initial penalty = " << factor
       << "\n  set Initial penalty scaling = nodal compliance\n"
       << "  set Regularisation = " << regularisation
       << "\nend\nsubsection Output\n  set Write solution = false\n"
       << "  set Print timing = false\n  set Output directory = results\nend\n";
  auto               problem = hrcontact_tests::solve_from_text<2>(text.str());
  std::ostringstream quiet;
  problem->output_results(quiet);
  return problem;
}

int
main()
{
  const auto   al      = run("consistent augmented Lagrangian", 1e4);
  const double p_scale = al->results().summary.get_double("max_abs_p_n");
  std::cout << "consistent augmented Lagrangian: "
            << (*al->results().contact).history.size()
            << " updates, tension / max |p| < 1e-10 (its tolerance): "
            << hrcontact_tests::check(
                 al->results().summary.get_double("max_positive_p_n") / p_scale,
                 1e-10)
            << std::endl;
  double previous_tension = 0;
  for (const double factor : {1e4, 1e6, 1e8})
    {
      const auto   pp = run("pure penalty", factor);
      const double tension =
        pp->results().summary.get_double("max_positive_p_n");
      double p_error = 0;
      for (unsigned int k = 0; k < al->results().reactions.contact.size(); ++k)
        p_error = std::max(p_error,
                           std::abs(pp->results().reactions.contact[k] -
                                    al->results().reactions.contact[k]));
      std::cout << "pure penalty, alpha = " << std::setprecision(1) << factor
                << " x nodal compliance: converged = "
                << pp->results().summary.get("converged") << ", "
                << (*pp->results().contact).total_newton_steps
                << " Newton steps, tension / max |p| = " << std::scientific
                << std::setprecision(2) << tension / p_scale
                << ", max |p - p_AL| / max |p| = " << p_error / p_scale
                << std::defaultfloat << std::endl;
      if (previous_tension > 0)
        std::cout << "  tension falls as 1/alpha (ratio 100 to 5 %): "
                  << hrcontact_tests::check(
                       std::abs(previous_tension / tension / 100 - 1), 0.05)
                  << std::endl;
      previous_tension = tension;
    }
}
