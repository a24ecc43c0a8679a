// The no-tension and no-compression patch tests with the interior point
// (issue 54), which Method = automatic, the default, takes for DGQ1 and a
// linear elastic law: the bodies of no_tension_patch_test (4^dim distorted
// cells, u = eps x on the whole boundary, E = 1000, nu = 0.3, plane stress
// in 2D) with no Method set. summary.txt must name the interior point; a
// homogeneous state must come out as the closed form's at every point to
// what the barrier's allowance (1e-6 of the largest stress) and the last
// stage's tolerance leave, 1e-5 of the largest stress or of E |eps| where
// the stress is zero (a homogeneous tension: the whole strain a fracture
// strain), in at most 12 Newton steps (8 when written); the largest fracture
// strain must be the closed form's to 1e-5 of |eps| (the errors were 3e-8 to
// 5e-6). Where the interior point does not apply, automatic takes the
// augmented Lagrangian: Pian-Sumihara stresses, a Ramberg-Osgood law,
// Constraint points chosen (they belong to it). A traction only tension
// could carry is refused by name, and so is a Stress tolerance that is
// neither automatic nor a positive number.

#include "tests.h"

using namespace hrcontact_tests;

namespace
{
  const double E = 1000, nu = 0.3;

  template <int dim>
  void
  report(const ConePatchState &state)
  {
    const auto problem =
      solve_from_text<dim>(constraint_patch<dim>(state.constraint, state.eps));
    const auto &r = problem->results();
    const auto [max_err, l2_err] =
      stress_errors<dim>(r, stress_reference<dim>(state.sigma));
    const auto [absolute, strain] = patch_error_scales(state, E);
    std::cout << "  " << state.name << " ('" << state.constraint
              << "'): method: " << r.stress_constraint.gauss_point_method
              << ", in at most 12 Newton steps: "
              << (r.material.newton_steps <= 12 ? "yes" : "NO")
              << "\n    stresses against the closed form, max < 1e-5: "
              << check(max_err / absolute, 1e-5)
              << ", L2 < 1e-5: " << check(l2_err / absolute, 1e-5)
              << "\n    largest fracture strain against " << state.opening
              << " to 1e-5: "
              << check(std::abs(r.stress_constraint.largest_fracture_strain -
                                state.opening) /
                         strain,
                       1e-5)
              << std::endl;
  }

  /** The method automatic takes for a body with these settings. */
  std::string
  method_taken(const std::string &settings)
  {
    double eps[3][3];
    rotated(-1e-3, -2e-3, 30, eps);
    const auto problem =
      solve_from_text<2>(constraint_patch<2>("no tension", eps, settings));
    const auto &c = problem->results().stress_constraint;
    return c.residuals.empty() ? c.gauss_point_method : "augmented Lagrangian";
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  for (const auto &state : cone_patch_states(E, nu))
    (state.dim == 2 ? report<2> : report<3>)(state);

  std::cout << "What automatic takes:\n"
            << "  DGQ1, linear elastic: " << method_taken("") << '\n'
            << "  Pian-Sumihara, linear elastic: "
            << method_taken("subsection Finite elements\n"
                            "  set Stress element = Pian-Sumihara\nend\n")
            << '\n'
            << "  DGQ1, linear elastic, Constraint points = cell centres: "
            << method_taken("subsection Stress constraint iteration\n"
                            "  set Constraint points = cell centres\nend\n")
            << '\n'
            << "  DGQ1, Ramberg-Osgood: "
            << method_taken("subsection Material\n"
                            "  set Model = Ramberg-Osgood\n"
                            "  set Ramberg-Osgood coefficient = 3/7\n"
                            "  set Ramberg-Osgood reference stress = 1\n"
                            "  set Ramberg-Osgood exponent = 5\nend\n")
            << '\n';

  std::cout << "Stress tolerance = fast: ";
  try
    {
      double eps[3][3] = {};
      solve_from_text<2>(
        constraint_patch<2>("no tension",
                            eps,
                            "subsection Stress constraint iteration\n"
                            "  set Stress tolerance = fast\nend\n"));
      std::cout << "NOT refused\n";
    }
  catch (const hrcontact::InputError &e)
    {
      std::cout << "refused, naming the entry: "
                << (std::string(e.what()).find("Stress tolerance") !=
                        std::string::npos ?
                      "yes" :
                      "NO")
                << '\n';
    }
  std::cout << "A traction that needs tension: " << tension_traction_refusal("")
            << '\n';
}
