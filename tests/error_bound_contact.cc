// The guaranteed error bound with unilateral contact (doc/error-bounds.md,
// ContactTractions):
// - parameters/signorini-error-bound.prm, whose exact solution is known
//   (the contact zone ends at x = 1/2 with zero pressure), at 4 x 4 to
//   16 x 16 cells: effectivity in [1, 2], the reconstruction admissible to
//   1e-9 (its tractions on the contact faces carry the nodal reactions and
//   are compressive), the bound halves with h, the inequality |u - u_h|^2 +
//   |sigma - tau|^2 <= eta^2 holds, the discrete contact zone ends within
//   one node of x = 1/2;
// - the displacement pushed into the obstacle: lifted back (its
//   penetration shows), the bound grows and stays above the pushed field's
//   true error;
// - parameters/hertz.prm at 192 cells (a curved body on a straight
//   obstacle, released nodes with round-off reactions): admissible to 1e-9,
//   no lift, the contact term's share below 1e-6;
// - a curved obstacle is refused by name.



#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/core/input.h>

#include "error_bound_check.h"
#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  std::string
  signorini(const unsigned int refinements)
  {
    return scene_at_refinement("signorini-error-bound", 2, refinements);
  }

  const std::string exact_stress =
    "if(x<x0, -b*lam*(x-x0)^2, -6*k*y*(lam+2*mu)*(x-x0)); if(x<x0, "
    "-b*(lam+2*mu)*(x-x0)^2, -6*k*lam*y*(x-x0)); if(x<x0, -2*b*mu*y*(x-x0), 0)";
} // namespace

int
main()
{
  std::vector<double> bounds;
  for (const unsigned int r : {1u, 2u, 3u})
    {
      const auto         problem = solve_from_text<2>(signorini(r));
      std::ostringstream quiet;
      problem->output_results(quiet);
      const auto      &res = problem->results();
      const auto      &s   = res.summary;
      const BoundCheck b   = bound_against(res, exact_stress);
      const double     eff = s.get_double("effectivity_index");
      // Pressed nodes: x <= 1/2 is n / 2 + 1 of the base's n + 1.
      const unsigned int n       = 2u << r;
      unsigned int       pressed = 0;
      for (const bool released : res.contact->released)
        pressed += released ? 0 : 1;
      std::cout
        << n << " x " << n << " cells: effectivity in [1, 2]: "
        << (eff >= 1 && eff <= 2 ? "yes" : "NO") << " (" << std::setprecision(3)
        << eff << "), the summary's bound "
        << "is the inequality's: "
        << check(std::abs(s.get_double("error_bound") / b.eta - 1), 1e-8)
        << "\n  tau admissible to 1e-9: " << check(b.admissible, 1e-9)
        << ", |u - u_h|^2 + |sigma - tau|^2 <= eta^2 (1 + 1e-9): "
        << check(b.slack, 1e-9) << "\n  contact term's share "
        << (s.get_double("error_bound_contact_share") >= 0 ? "nonnegative" :
                                                             "NEGATIVE")
        << ", no penetration to lift: "
        << check(s.get_double("error_bound_lift"), 0) << ", pressed nodes "
        << pressed << " (exact " << n / 2 + 1 << ", within one: "
        << (pressed + 1 >= n / 2 + 1 && pressed <= n / 2 + 2 ? "yes" : "NO")
        << ")" << std::endl;
      bounds.push_back(b.eta);
    }
  for (unsigned int i = 1; i < bounds.size(); ++i)
    std::cout << "  bound ratio to the previous mesh in [1.8, 2.2]: "
              << (bounds[i - 1] / bounds[i] >= 1.8 &&
                      bounds[i - 1] / bounds[i] <= 2.2 ?
                    "yes" :
                    "NO")
              << std::endl;

  // u_h pushed into the obstacle by c (1 - y / 2) (1 + x): v = u_h + w
  // lifts the base's nodes back; the bound covers the pushed field.
  {
    const auto   problem = solve_from_text<2>(signorini(2));
    auto         pushed(problem->results());
    const auto   support = displacement_support_points(pushed);
    const double c       = 0.05 * pushed.displacement.linfty_norm();
    for (unsigned int i = 1; i < support.size(); i += 2)
      pushed.displacement(i) -=
        c * (1 - support[i][1] / 2) * (1 + support[i][0]);
    report_pushed("the obstacle",
                  bound_against(problem->results(), exact_stress),
                  bound_against(pushed, exact_stress),
                  c);
  }

  // Hertz: the cylinder on the plane, 192 cells.
  {
    std::string text =
      read_file(std::string(SOURCE_DIR) + "/../parameters/hertz.prm");
    const std::string from = "set Global refinements = 4";
    text.replace(text.find(from), from.size(), "set Global refinements = 3");
    const auto problem = solve_from_text<2>(
      text + "subsection Postprocess\n  set Error bound = true\n"
             "  set Pressure plot = false\nend\n"
             "subsection Output\n  set Write solution = false\n"
             "  set Output directory = results-hertz\nend\n");
    std::ostringstream quiet;
    problem->output_results(quiet);
    const auto &s = problem->results().summary;
    std::cout
      << "Hertz, " << s.get("cells") << " cells: tau admissible to 1e-9: "
      << check(std::max(s.get_double("error_bound_traction_residual"),
                        s.get_double("error_bound_equilibrium_residual")),
               1e-9)
      << ", no lift: " << check(s.get_double("error_bound_lift"), 0)
      << ", contact term's share below 1e-6: "
      << check(s.get_double("error_bound_contact_share"), 1e-6) << ", bound "
      << std::setprecision(3) << 100 * s.get_double("error_bound_relative")
      << " %" << std::endl;
  }

  // A curved obstacle: the gap is not linear along a face.
  std::string text = signorini(1);
  text.replace(text.find("set Obstacles = 2: 0, 0 : 0, -1"),
               std::string("set Obstacles = 2: 0, 0 : 0, -1").size(),
               "set Curved obstacles = 2: circle : 0.5, -10 : 10");
  print_input_refusal("curved obstacle", text);
}
