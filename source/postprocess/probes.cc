#include <deal.II/base/utilities.h>

#include <hrcontact/discretisation/stress_constraint_field.h>
#include <hrcontact/postprocess/field_values.h>
#include <hrcontact/postprocess/probes.h>

#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  Probes<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Probes",
      "",
      Patterns::Anything(),
      "Quantities at points, reported in the log and summary.txt as "
      "probe.NAME: 'name: x, y [, z] : quantity', entries separated by '|'. "
      "Coordinates are expressions of the constants; quantity is one of ux, "
      "uy, uz, sxx, syy, szz, sxy, sxz, syz, von_mises. A stress at a point "
      "shared by cells is taken from the first cell found.");
    prm.declare_entry(
      "Reference values",
      "",
      Patterns::Anything(),
      "Reference values of probes, e.g. from beam theory: 'name: expression' "
      "with the name of a probe; summary.txt gets reference.NAME and "
      "relative_error.NAME.");
    prm.declare_entry(
      "Reference stress",
      "",
      Patterns::Anything(),
      "An exact stress field to measure the error against: expressions in "
      "x, y (, z) for sxx; syy; sxy (2D) or sxx; syy; szz; sxy; sxz; syz "
      "(3D). summary.txt gets stress_error_max and stress_error_l2, relative "
      "to the same norms of the reference. Empty: no comparison.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Probes<dim>::parse_parameters(ParameterHandler &prm,
                                const Constants  &constants)
  {
    static const std::vector<std::string> quantities = {
      "ux", "uy", "uz", "sxx", "syy", "szz", "sxy", "sxz", "syz", "von_mises"};
    prm.enter_subsection("Postprocess");
    for (const auto &[name, text] :
         parse_named_list(prm.get("Probes"), "Postprocess/Probes"))
      {
        const auto        parts = split_and_trim(text, ':');
        const std::string where = "Postprocess/Probes, '" + name + "'";
        if (parts.size() != 2)
          throw InputError(where + ": expected 'name: x, y : quantity'.");
        const auto coords = split_and_trim(parts[0], ',');
        if (coords.size() != dim)
          throw InputError(where + ": expected " + std::to_string(dim) +
                           " coordinates separated by ','.");
        Probe probe;
        probe.name = name;
        for (unsigned int d = 0; d < dim; ++d)
          probe.point[d] =
            evaluate_constant_expression(coords[d], constants, where);
        probe.quantity = parts[1];
        bool known     = false;
        for (const auto &q : quantities)
          known |= (q == probe.quantity);
        if (!known ||
            (dim == 2 && probe.quantity.find('z') != std::string::npos))
          throw InputError(where + ": unknown quantity '" + probe.quantity +
                           "' in " + std::to_string(dim) + "D.");
        probes.push_back(probe);
      }
    for (const auto &[name, expr] :
         parse_named_list(prm.get("Reference values"),
                          "Postprocess/Reference values"))
      {
        bool found = false;
        for (const auto &p : probes)
          found |= (p.name == name);
        if (!found)
          throw InputError("Postprocess/Reference values: '" + name +
                           "' is not the name of a probe.");
        reference_values.emplace_back(
          name,
          evaluate_constant_expression(
            expr, constants, "Postprocess/Reference values, '" + name + "'"));
      }
    reference_stress = parse_reference_stress<dim>(prm, constants);
    prm.leave_subsection();
  }

  template <int dim>
  void
  Probes<dim>::check_input(const Scene<dim> &,
                           const Triangulation<dim> &triangulation,
                           const EquilibriumSystem &) const
  {
    for (const Probe &probe : probes)
      if (!mesh_contains_point(triangulation, probe.point))
        {
          std::ostringstream point;
          for (unsigned int d = 0; d < dim; ++d)
            point << (d ? ", " : "") << probe.point[d];
          throw InputError("Postprocess/Probes, '" + probe.name +
                           "': the point (" + point.str() +
                           ") is outside the body (no cell of the mesh "
                           "contains it).");
        }
  }

  template <int dim>
  void
  Probes<dim>::execute(const Results<dim> &results, PostprocessOutput &output)
  {
    Summary      &summary = output.summary;
    std::ostream &log     = output.log;
    if (!probes.empty())
      log << "  probes:\n";
    for (const Probe &probe : probes)
      {
        const double value = point_value(results, probe.point, probe.quantity);
        summary.add("probe." + probe.name, value);
        log << "    " << std::left << std::setw(20) << probe.name << std::right
            << std::setw(8) << probe.quantity << " = " << std::setw(14)
            << std::setprecision(6) << value;
        // Where cracks open the displacements are not unique (eq. 50-51
        // recover one compatible choice): say so next to such a probe.
        if (results.stress_constraint.field && probe.quantity[0] == 'u')
          {
            const auto  &field   = *results.stress_constraint.field;
            const double largest = field.largest_opening();
            const bool   cracked =
              largest > 0 && field.opening_at(probe.point) > 1e-2 * largest;
            summary.add("probe_in_cracked_region." + probe.name,
                        cracked ? "true" : "false");
            if (cracked)
              log << "   (in a cracked region: displacements there are not "
                     "unique, doc/materials.md)";
          }
        for (const auto &[name, ref] : reference_values)
          if (name == probe.name)
            {
              const double err =
                (ref != 0) ? (value - ref) / std::abs(ref) : value - ref;
              summary.add("reference." + name, ref);
              summary.add("relative_error." + name, err);
              log << "   reference " << std::setw(14) << ref
                  << "   relative error " << std::setprecision(3) << err;
            }
        log << '\n';
      }
    if (reference_stress)
      {
        const auto [max_err, l2_err] =
          stress_error(results.spaces, results.stress, *reference_stress);
        summary.add("stress_error_max", max_err);
        summary.add("stress_error_l2", l2_err);
        log << "  stress error against the reference field: max "
            << std::setprecision(3) << max_err << ", L2 " << l2_err
            << " (relative)\n";
      }
    log << std::flush;
  }

  template class Probes<2>;
  template class Probes<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    Probes,
    "probes",
    20,
    "quantities at points (Probes), their Reference values, the error "
    "against a Reference stress")
} // namespace hrcontact
