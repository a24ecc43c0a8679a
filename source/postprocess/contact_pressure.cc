#include <deal.II/base/geometry_info.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/material/linear_elasticity.h>
#include <hrcontact/postprocess/contact_pressure.h>
#include <hrcontact/postprocess/sorted_rows.h>

#include <cmath>
#include <iomanip>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  ContactPressure<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Hertz load",
      "",
      Patterns::Anything(),
      "2D contact: the total load per unit length P on the full cylinder of a "
      "Hertz problem (an expression of the constants). With Hertz radius set, "
      "summary.txt compares contact_half_width and peak_pressure with "
      "hertz_half_width = sqrt(4 P R / (pi E*)) and hertz_peak_pressure = 2 "
      "P / (pi a), E* = E/(1 - nu^2). Empty: no comparison.");
    prm.declare_entry("Hertz radius",
                      "",
                      Patterns::Anything(),
                      "The cylinder radius R of the Hertz comparison; two "
                      "cylinders: 1/R = 1/R1 + 1/R2.");
    prm.declare_entry(
      "Hertz modulus",
      "",
      Patterns::Anything(),
      "The contact modulus E* of the Hertz comparison (an expression of the "
      "constants); two bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. "
      "Empty: E/(1 - nu^2) of the scene's material (a body on a rigid "
      "obstacle).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ContactPressure<dim>::parse_parameters(ParameterHandler &prm,
                                         const Constants &)
  {
    prm.enter_subsection("Postprocess");
    hertz_load    = prm.get("Hertz load");
    hertz_radius  = prm.get("Hertz radius");
    hertz_modulus = prm.get("Hertz modulus");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  ContactPressure<dim>::skip_reason(const Results<dim> &results) const
  {
    if (!results.contact)
      return "the scene has no contact";
    if (dim != 2)
      return "contact pressures are computed in 2D only";
    if (results.scene.lining)
      return "tunnel linings report their extrados pressure (tunnel lining)";
    return "";
  }

  template <int dim>
  void
  ContactPressure<dim>::execute(const Results<dim> &results,
                                PostprocessOutput  &output)
  {
    const EquilibriumSystem &system  = results.system;
    Summary                 &summary = output.summary;
    std::ostream            &log     = output.log;
    // Pressure at a node = -p / (half the lengths of its two neighbouring
    // contact edges): the nodal reaction spread over its tributary length.
    // Assumes the contact boundary is one curve, monotone in x.
    const std::vector<unsigned int> order = sorted_contact_rows(system);
    const unsigned int              nc    = order.size();
    auto                            point = [&](const unsigned int j) {
      const auto &c =
        system
          .node_coordinates[system.rows[system.contact_rows[order[j]]].node];
      return Point<2>(c[0], c[1]);
    };
    double peak = 0, zone_end = 0;
    bool   any_pressed = false;
    for (unsigned int j = 0; j < nc; ++j)
      {
        const double left = (j > 0) ? point(j).distance(point(j - 1)) : 0.;
        const double right =
          (j + 1 < nc) ? point(j).distance(point(j + 1)) : 0.;
        const double       tributary = 0.5 * (left + right);
        const unsigned int k         = order[j];
        if (!results.contact->released[k] && tributary > 0)
          {
            any_pressed = true;
            peak = std::max(peak, -results.reactions.contact[k] / tributary);
            // The zone ends halfway to the next open node.
            zone_end =
              point(j)[0] +
              ((j + 1 < nc && results.contact->released[order[j + 1]]) ?
                 0.5 * (point(j + 1)[0] - point(j)[0]) :
                 0.);
          }
      }
    double zone_start = 0;
    for (unsigned int j = 0; j < nc; ++j)
      if (!results.contact->released[order[j]])
        {
          zone_start = point(j)[0] -
                       ((j > 0) ? 0.5 * (point(j)[0] - point(j - 1)[0]) : 0.);
          break;
        }
    summary.add("peak_pressure", any_pressed ? peak : 0.);
    summary.add("contact_zone_x_min", zone_start);
    summary.add("contact_zone_x_max", zone_end);
    if (Utilities::trim(hertz_load).empty() ||
        Utilities::trim(hertz_radius).empty())
      return;
    // Plane strain Hertz contact of a cylinder on a rigid plane; the half
    // model's pressed zone starts at the symmetry plane.
    const double P      = evaluate_constant_expression(hertz_load,
                                                  results.scene.constants,
                                                  "Postprocess/Hertz load");
    const double R      = evaluate_constant_expression(hertz_radius,
                                                  results.scene.constants,
                                                  "Postprocess/Hertz radius");
    double       E_star = 0;
    if (!Utilities::trim(hertz_modulus).empty())
      E_star = evaluate_constant_expression(hertz_modulus,
                                            results.scene.constants,
                                            "Postprocess/Hertz modulus");
    else
      {
        const auto *elastic = dynamic_cast<const LinearElasticity<dim> *>(
          results.scene.material.get());
        if (!elastic)
          throw InputError("Postprocess/Hertz load: the Hertz comparison "
                           "needs Material/Model = linear elasticity or a "
                           "Hertz modulus.");
        const double nu = elastic->poisson_ratio();
        E_star          = elastic->youngs_modulus() / (1 - nu * nu);
      }
    const double a_hertz = std::sqrt(4 * P * R / (numbers::PI * E_star));
    const double p_hertz = 2 * P / (numbers::PI * a_hertz);
    const double a       = zone_end - zone_start;
    summary.add("contact_half_width", a);
    summary.add("hertz_half_width", a_hertz);
    summary.add("relative_error_half_width", (a - a_hertz) / a_hertz);
    summary.add("hertz_peak_pressure", p_hertz);
    summary.add("relative_error_peak_pressure", (peak - p_hertz) / p_hertz);
    log << "  Hertz: half width " << std::setprecision(5) << a << " (Hertz "
        << a_hertz << ", error " << std::setprecision(3)
        << 100 * (a - a_hertz) / a_hertz << " %), peak pressure "
        << std::setprecision(5) << peak << " (Hertz " << p_hertz << ", error "
        << std::setprecision(3) << 100 * (peak - p_hertz) / p_hertz << " %)"
        << std::endl;
  }

  template class ContactPressure<2>;
  template class ContactPressure<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    ContactPressure,
    "contact pressure",
    60,
    "2D contact: peak pressure and contact zone, the Hertz comparison")
} // namespace hrcontact
