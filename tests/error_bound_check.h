// The bound of a solved 2D scene against its exact stresses, for the error
// bound's tests (error_bound_contact, error_bound_contact_pair).

#ifndef hrcontact_tests_error_bound_check_h
#define hrcontact_tests_error_bound_check_h

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/core/input.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace hrcontact_tests
{
  /** The bound, the true error, the inequality's slack (|u - u_h|^2 +
   * |sigma - tau|^2 over eta^2, less 1), the reconstruction's largest
   * residual, the lift's energy and the largest penetration it lifts. */
  struct BoundCheck
  {
    double eta, error, slack, admissible, lift, penetration;
  };

  /** The support point of every displacement dof of @p results, for
   * perturbing the displacement as a function of position. */
  inline std::vector<dealii::Point<2>>
  displacement_support_points(const hrcontact::Results<2> &results)
  {
    const auto                   &dh = results.spaces.dof_handler_displacement;
    std::vector<dealii::Point<2>> support(dh.n_dofs());
    dealii::DoFTools::map_dofs_to_support_points(
      dealii::StaticMappingQ1<2>::mapping, dh, support);
    return support;
  }

  /** Reconstructs tau from @p results and compares with @p exact_stress
   * (xx; yy; xy in the scene's constants). */
  inline BoundCheck
  bound_against(const hrcontact::Results<2> &results,
                const std::string           &exact_stress)
  {
    hrcontact::EquilibratedStress<2> tau(results);
    tau.compute();
    const auto   reference = hrcontact::make_function<2>(exact_stress,
                                                       3,
                                                       results.scene.constants,
                                                       "test");
    const auto   c         = tau.compare(*reference);
    const double eta       = tau.bound();
    return {eta,
            std::sqrt(c.displacement_error_squared),
            (c.displacement_error_squared + c.reconstruction_error_squared) /
                (eta * eta) -
              1,
            std::max(tau.traction_residual, tau.cell_residual),
            tau.lift,
            tau.largest_penetration};
  }

  /** The line of a displacement pushed by at most @p c into what it must
   * not penetrate: lifted back, and its bound @p b grows from @p original
   * and stays above its own true error. */
  inline void
  report_pushed(const std::string &into,
                const BoundCheck  &original,
                const BoundCheck  &b,
                const double       c)
  {
    std::cout << "pushed into " << into << ": penetration lifted "
              << (b.penetration > 0 && b.penetration <= 2 * c ?
                    "(0, 2 c]" :
                    "NOT in (0, 2 c]")
              << ", lift energy positive: " << (b.lift > 0 ? "yes" : "NO")
              << ", the bound grows: " << (b.eta > original.eta ? "yes" : "NO")
              << ", stays above the true error: "
              << (b.eta >= b.error ? "yes" : "NO") << std::endl;
  }
} // namespace hrcontact_tests

#endif
