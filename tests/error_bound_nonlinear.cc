// The guaranteed error bound for a nonlinear law (doc/error-bounds.md): the
// Fenchel-Young gap 2 int [phi^c(tau) + W(eps(u_h)) - tau : eps(u_h)] on
// parameters/ramberg-osgood-error-bound.prm (a Ramberg-Osgood beam in pure
// bending, n = 3, its exact stress by Cardano's formula) at 160, 640 and
// 2,560 cells:
// - effectivity in [1, 2] (the true error in the same measure: twice the
//   Bregman distance of phi^c from the stress of u_h's strain to the exact
//   stress);
// - the bound halves with h (ratio in [1.6, 2.2]);
// - the identity gap = |u - u_h|^2 + |sigma - tau|^2 (both Bregman) up to
//   the end tractions' projection (they are not polynomial): its defect
//   falls by at least 4 per refinement, the cells' equilibrium residual by 3;
//   the vertex problems' residual at round-off;
// - a perturbed displacement: the bound grows and stays above the
//   perturbed field's true error.

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/core/input.h>

#include "tests.h"

using namespace hrcontact_tests;

int
main()
{
  std::vector<double> bounds, defects, residuals;
  for (const unsigned int r : {2u, 3u, 4u})
    {
      const auto problem = solve_from_text<2>(
        scene_at_refinement("ramberg-osgood-error-bound", 2, r));
      std::ostringstream quiet;
      problem->output_results(quiet);
      const auto  &s   = problem->results().summary;
      const double eff = s.get_double("effectivity_index");
      std::cout << s.get("cells") << " cells, "
                << s.get("material_newton_steps")
                << " material Newton steps: effectivity in [1, 2]: "
                << (eff >= 1 && eff <= 2 ? "yes" : "NO") << " ("
                << std::setprecision(3) << eff << "), vertex problems at "
                << "round-off: "
                << check(s.get_double("error_bound_traction_residual"), 1e-10)
                << std::endl;
      bounds.push_back(s.get_double("error_bound"));
      defects.push_back(s.get_double("hypercircle_defect"));
      residuals.push_back(s.get_double("error_bound_equilibrium_residual"));
    }
  for (unsigned int i = 1; i < bounds.size(); ++i)
    std::cout << "  to the next mesh: bound ratio in [1.6, 2.2]: "
              << (bounds[i - 1] / bounds[i] >= 1.6 &&
                      bounds[i - 1] / bounds[i] <= 2.2 ?
                    "yes" :
                    "NO")
              << ", identity defect / 4 or less: "
              << (defects[i] <= defects[i - 1] / 4 ? "yes" : "NO")
              << ", equilibrium residual / 3 or less: "
              << (residuals[i] <= residuals[i - 1] / 3 ? "yes" : "NO")
              << std::endl;

  // The displacement perturbed by a smooth field (only point supports: v
  // stays admissible): the bound of v grows and stays above v's error.
  const auto problem =
    solve_from_text<2>(scene_at_refinement("ramberg-osgood-error-bound", 2, 2));
  auto                          perturbed(problem->results());
  const auto                   &dh = perturbed.spaces.dof_handler_displacement;
  std::vector<dealii::Point<2>> support(dh.n_dofs());
  dealii::DoFTools::map_dofs_to_support_points(
    dealii::StaticMappingQ1<2>::mapping, dh, support);
  const double umax = perturbed.displacement.linfty_norm();
  for (unsigned int i = 0; i < support.size(); ++i)
    perturbed.displacement(i) +=
      0.02 * umax * std::sin(3 * support[i][0]) * support[i][1] / 0.05;
  hrcontact::EquilibratedStress<2> original(problem->results()),
    shifted(perturbed);
  original.compute();
  shifted.compute();
  const auto reference = hrcontact::make_function<2>(
    "sign(K*y/2 + sqrt(K^2*y^2/4 + P^3/27))*abs(K*y/2 + sqrt(K^2*y^2/4 + "
    "P^3/27))^(1/3) + sign(K*y/2 - sqrt(K^2*y^2/4 + P^3/27))*abs(K*y/2 - "
    "sqrt(K^2*y^2/4 + P^3/27))^(1/3); 0; 0",
    3,
    perturbed.scene.constants,
    "test");
  const double e =
    std::sqrt(shifted.compare(*reference).displacement_error_squared);
  std::cout << "perturbed displacement: the bound grows: "
            << (shifted.bound() > original.bound() ? "yes" : "NO")
            << ", stays above the true error: "
            << (shifted.bound() >= e ? "yes" : "NO") << std::endl;
}
