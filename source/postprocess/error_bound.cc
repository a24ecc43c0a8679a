#include <deal.II/base/timer.h>

#include <hrcontact/adaptivity/cell_equilibration.h>
#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/adaptivity/support_mismatch.h>
#include <hrcontact/postprocess/error_bound.h>
#include <hrcontact/postprocess/field_values.h>

#include <cmath>
#include <iomanip>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  ErrorBound<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Error bound",
      "false",
      Patterns::Bool(),
      "Compute a guaranteed upper bound of the displacements' energy error "
      "from an equilibrated stress (Prager-Synge; doc/error-bounds.md): "
      "summary.txt gets error_bound (absolute), error_bound_relative (to the "
      "energy of the computed stresses) and how exactly the reconstruction "
      "is admissible; with a Reference stress also the true energy error "
      "and the effectivity index; with contact the contact term's share. "
      "So far 2D (hanging nodes included), linear elastic and Ramberg-Osgood "
      "bodies (the Fenchel-Young gap), contact with straight obstacles "
      "(Contact/Obstacles) and between bodies whose meshes match across a "
      "straight interface (Contact/Contact pairs), Supports/Normal "
      "displacements along an axis; 3D on meshes of parallelepipeds, linear "
      "elastic bodies.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ErrorBound<dim>::parse_parameters(ParameterHandler &prm,
                                    const Constants  &constants)
  {
    prm.enter_subsection("Postprocess");
    compute = prm.get_bool("Error bound");
    if (compute)
      reference_stress = parse_reference_stress<dim>(prm, constants);
    prm.leave_subsection();
    // Bound-driven cycles compute the bound too (BoundIndicator, the target
    // error): what it does not cover is refused before the first solve.
    prm.enter_subsection("Mesh refinement");
    check = compute || Utilities::trim(prm.get("Estimator")) == "bound" ||
            prm.get_double("Target error") > 0;
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  ErrorBound<dim>::skip_reason(const Results<dim> &) const
  {
    return compute ? "" : "Postprocess/Error bound is false";
  }

  template <int dim>
  void
  ErrorBound<dim>::check_input(const Scene<dim> &scene,
                               const Triangulation<dim> &,
                               const EquilibriumSystem &system) const
  {
    if (check)
      {
        EquilibratedStress<dim>::check_scene(scene);
        EquilibratedStress<dim>::check_rows(system);
      }
  }

  template <int dim>
  void
  ErrorBound<dim>::execute(const Results<dim> &results,
                           PostprocessOutput  &output)
  {
    Timer                   timer;
    EquilibratedStress<dim> tau(results);
    tau.compute();
    const double seconds = timer.wall_time();
    const double eta     = tau.bound();
    const double energy  = std::sqrt(tau.solution_energy_squared());
    Summary     &summary = output.summary;
    summary.add("error_bound", eta);
    summary.add("error_bound_relative", energy > 0 ? eta / energy : eta);
    summary.add("error_bound_traction_residual", tau.traction_residual);
    summary.add("error_bound_equilibrium_residual", tau.cell_residual);
    summary.add("error_bound_seconds", seconds);
    // u_h must meet the prescribed displacements between the nodes too.
    const double mismatch = support_mismatch(results);
    summary.add("error_bound_support_mismatch", mismatch);
    if (!results.system.contact_rows.empty())
      {
        // The contact term's share of eta^2, and the lift that makes u_h
        // non-penetrating (0 when the contact rows hold at the nodes).
        summary.add("error_bound_contact_share",
                    eta > 0 ? tau.contact_term / (eta * eta) : 0.);
        summary.add("error_bound_lift", tau.lift);
        summary.add("error_bound_largest_penetration", tau.largest_penetration);
      }
    // Each cell's eta_K (its square sums to eta^2) for solution.vtu.
    Vector<float> &indicators = output.cell_fields["error_bound_indicator"];
    indicators.reinit(tau.cell_bound_squared().size());
    for (unsigned int k = 0; k < indicators.size(); ++k)
      indicators[k] = std::sqrt(tau.cell_bound_squared()[k]);
    output.log << "  error bound (Prager-Synge, equilibrated stress of "
                  "degree "
               << CellEquilibration::degree << "): " << std::setprecision(4)
               << eta << " (" << 100 * eta / energy
               << " % of the stresses' energy norm), admissible to "
               << std::setprecision(2)
               << std::max(tau.traction_residual, tau.cell_residual) << ", "
               << std::setprecision(3) << seconds << " s\n";
    if (mismatch > 1e-8)
      output.log << "  warning: u_h misses the prescribed displacements "
                    "between the nodes by "
                 << std::setprecision(2) << mismatch
                 << " of its largest value (Q1 meets only values linear "
                    "along each face): the bound leaves that interpolation "
                    "error out and is not guaranteed\n";
    if (reference_stress)
      {
        const auto   c = tau.compare(*reference_stress);
        const double e = std::sqrt(c.displacement_error_squared);
        summary.add("energy_error", e);
        summary.add("energy_error_relative",
                    e / std::sqrt(c.reference_energy_squared));
        summary.add("effectivity_index", e > 0 ? eta / e : 0.);
        summary.add("stress_error_energy",
                    std::sqrt(c.stress_error_squared /
                              c.reference_energy_squared));
        // |u - u_h|^2 + |sigma - tau|^2 = eta^2 for an admissible tau.
        summary.add("hypercircle_defect",
                    std::abs(c.displacement_error_squared +
                             c.reconstruction_error_squared - eta * eta) /
                      (eta * eta));
        output.log << "    against the Reference stress: energy error "
                   << std::setprecision(4) << e << ", effectivity " << eta / e
                   << std::endl;
      }
  }

  template class ErrorBound<2>;
  template class ErrorBound<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    ErrorBound,
    "error bound",
    25,
    "a guaranteed bound of the energy error from an equilibrated stress "
    "(Error bound)")
} // namespace hrcontact
