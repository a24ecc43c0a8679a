#include <deal.II/base/geometry_info.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/material/linear_elasticity.h>
#include <hrcontact/postprocess/contact_pressure.h>
#include <hrcontact/postprocess/pressure_plot.h>
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
      "Pressure plot",
      "false",
      Patterns::Bool(),
      "2D contact: write pressure.csv (x, y, nodal pressure, status, Hertz's "
      "pressure), the gnuplot script pressure.gp and, where gnuplot is "
      "installed, pressure.png: the nodal contact pressure along x against "
      "Hertz's ellipse when Hertz load and radius are set.");
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
    plot          = prm.get_bool("Pressure plot");
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

  namespace
  {
    /**
     * The nodal pressures along the contact boundary, in the order of x:
     * -p over the node's tributary length, half the lengths of its two
     * neighbouring contact edges (the nodal reaction spread over its
     * share). Assumes the contact boundary is one curve, monotone in x.
     */
    template <int dim>
    std::vector<PressurePoint>
    pressure_profile(const Results<dim> &results)
    {
      const EquilibriumSystem        &system = results.system;
      const std::vector<unsigned int> order  = sorted_contact_rows(system);
      auto                            point  = [&](const unsigned int j) {
        const auto &c =
          system
            .node_coordinates[system.rows[system.contact_rows[order[j]]].node];
        return Point<2>(c[0], c[1]);
      };
      std::vector<PressurePoint> profile(order.size());
      for (unsigned int j = 0; j < order.size(); ++j)
        {
          const double left = (j > 0) ? point(j).distance(point(j - 1)) : 0.;
          const double right =
            (j + 1 < order.size()) ? point(j).distance(point(j + 1)) : 0.;
          const double       tributary = 0.5 * (left + right);
          const unsigned int k         = order[j];
          profile[j].x                 = point(j)[0];
          profile[j].y                 = point(j)[1];
          profile[j].pressed           = !results.contact->released[k];
          profile[j].pressure =
            tributary > 0 ? -results.reactions.contact[k] / tributary : 0.;
        }
      return profile;
    }

    /** The peak pressure and the zone [start, end] of the pressed nodes,
     * each end halfway to the next open node. */
    struct PressedZone
    {
      double peak = 0, start = 0, end = 0;
    };

    PressedZone
    pressed_zone(const std::vector<PressurePoint> &profile)
    {
      PressedZone zone;
      bool        found = false;
      const auto  n     = profile.size();
      for (unsigned int j = 0; j < n; ++j)
        if (profile[j].pressed)
          {
            if (!found)
              zone.start =
                profile[j].x -
                ((j > 0) ? 0.5 * (profile[j].x - profile[j - 1].x) : 0.);
            found     = true;
            zone.peak = std::max(zone.peak, profile[j].pressure);
            zone.end =
              profile[j].x + ((j + 1 < n && !profile[j + 1].pressed) ?
                                0.5 * (profile[j + 1].x - profile[j].x) :
                                0.);
          }
      return zone;
    }
  } // namespace

  template <int dim>
  HertzEllipse
  ContactPressure<dim>::hertz_ellipse(const Results<dim> &results) const
  {
    if (Utilities::trim(hertz_load).empty() ||
        Utilities::trim(hertz_radius).empty())
      return {};
    // Plane strain Hertz contact of a cylinder on a rigid plane; the half
    // model's pressed zone starts at the symmetry plane.
    const Constants &constants = results.scene.constants;
    const double     P         = evaluate_constant_expression(hertz_load,
                                                  constants,
                                                  "Postprocess/Hertz load");
    const double     R         = evaluate_constant_expression(hertz_radius,
                                                  constants,
                                                  "Postprocess/Hertz radius");
    double           E_star    = 0;
    if (!Utilities::trim(hertz_modulus).empty())
      E_star = evaluate_constant_expression(hertz_modulus,
                                            constants,
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
    HertzEllipse hertz;
    hertz.half_width = std::sqrt(4 * P * R / (numbers::PI * E_star));
    hertz.peak       = 2 * P / (numbers::PI * hertz.half_width);
    return hertz;
  }

  template <int dim>
  void
  ContactPressure<dim>::execute(const Results<dim> &results,
                                PostprocessOutput  &output)
  {
    Summary                         &summary = output.summary;
    std::ostream                    &log     = output.log;
    const std::vector<PressurePoint> profile = pressure_profile(results);
    const PressedZone                zone    = pressed_zone(profile);
    summary.add("peak_pressure", zone.peak);
    summary.add("contact_zone_x_min", zone.start);
    summary.add("contact_zone_x_max", zone.end);
    const HertzEllipse hertz = hertz_ellipse(results);
    if (hertz.half_width > 0)
      {
        const double a = zone.end - zone.start, a_hertz = hertz.half_width,
                     p_hertz = hertz.peak;
        summary.add("contact_half_width", a);
        summary.add("hertz_half_width", a_hertz);
        summary.add("relative_error_half_width", (a - a_hertz) / a_hertz);
        summary.add("hertz_peak_pressure", p_hertz);
        summary.add("relative_error_peak_pressure",
                    (zone.peak - p_hertz) / p_hertz);
        log << "  Hertz: half width " << std::setprecision(5) << a << " (Hertz "
            << a_hertz << ", error " << std::setprecision(3)
            << 100 * (a - a_hertz) / a_hertz << " %), peak pressure "
            << std::setprecision(5) << zone.peak << " (Hertz " << p_hertz
            << ", error " << std::setprecision(3)
            << 100 * (zone.peak - p_hertz) / p_hertz << " %)" << std::endl;
      }
    if (plot)
      for (const std::string &file : write_pressure_plot(
             profile, hertz, output.directory, output.communicator, log))
        output.mentioned_files.push_back(file);
  }

  template class ContactPressure<2>;
  template class ContactPressure<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    ContactPressure,
    "contact pressure",
    60,
    "2D contact: peak pressure and contact zone, the Hertz comparison")
} // namespace hrcontact
