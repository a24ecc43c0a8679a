#include <deal.II/base/timer.h>

#include <hrcontact/core/input.h>
#include <hrcontact/diagnostics/displacement_code_comparison.h>
#include <hrcontact/discretisation/displacement_law_stiffness.h>
#include <hrcontact/solvers/condensed/condensed_step.h>

#include <iomanip>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** max |a - b| over the owned entries of all processes. */
    double
    largest_difference(const FieldVector &a, const FieldVector &b)
    {
      FieldVector difference;
      difference.reinit(a, true);
      difference.copy_locally_owned_data_from(a);
      difference.add(-1., b);
      return difference.linfty_norm();
    }
  } // namespace

  template <int dim>
  void
  DisplacementCodeComparison<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Compare with a displacement code",
      "false",
      Patterns::Bool(),
      "Benchmarks for a nonlinear law (Material/Model = Ramberg-Osgood): "
      "after the run, solve the same scene the way a displacement code must, "
      "Newton's method on the Q1 displacements with the law inverted for the "
      "stress at every Gauss point and step, on the same supports, processes "
      "and linear solver, and report its Newton steps, the largest number "
      "of local inversion steps at a point, its wall time against the run's "
      "solve and the largest difference of its displacements from the run's "
      "(summary.txt: displacement_code_*; doc/materials.md). No contact and "
      "no stress constraint.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  DisplacementCodeComparison<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    enabled = prm.get_bool("Compare with a displacement code");
    prm.leave_subsection();
  }

  template <int dim>
  void
  DisplacementCodeComparison<dim>::check_scene(const Scene<dim> &scene,
                                               const bool has_contact) const
  {
    // A linear law has nothing to compare, and the displacement code has no
    // contact or stress constraint.
    if (enabled &&
        (scene.all_linear() || has_contact || scene.stress_constraint))
      throw InputError(
        "Output/Compare with a displacement code: only for a nonlinear "
        "material (Material/Model = Ramberg-Osgood) without contact or a "
        "stress constraint.");
  }

  template <int dim>
  void
  DisplacementCodeComparison<dim>::run(
    const MaterialIteration    &material_iteration,
    const LinearSolverSettings &linear_solver,
    Results<dim>               &r,
    std::ostream               &log) const
  {
    if (!enabled)
      return;
    // Newton on u from zero, each step's stiffness and load from the law
    // inverted at the Gauss points; the run's supports, processes and
    // linear solver. The first step is the elastic one.
    Timer                         timer;
    DisplacementLawStiffness<dim> law(r.scene, r.spaces);
    const unsigned int            nq = r.system.contact_rows.size();
    std::vector<double>           p, w(nq);
    FieldVector                   u, next;
    reinit_field(u, r.spaces.dof_handler_displacement);
    reinit_field(next, r.spaces.dof_handler_displacement);
    // The material iteration's stop: the tolerance, or the round-off floor
    // of the solves (here of the total displacements, near 1e-10 of them).
    std::vector<double> changes{1.};
    r.diagnostics.displacement_code_steps       = 0;
    r.diagnostics.displacement_code_local_steps = 0;
    while (changes.back() > material_iteration.relative_tolerance &&
           !MaterialIteration::at_roundoff(changes,
                                           material_iteration.roundoff_ceiling))
      {
        if (r.diagnostics.displacement_code_steps >=
            material_iteration.maximum_steps)
          throw NotConvergedError(
            "Output/Compare with a displacement code: no convergence in " +
            std::to_string(material_iteration.maximum_steps) +
            " Newton steps (Material iteration/Maximum steps).");
        r.diagnostics.displacement_code_local_steps =
          std::max(r.diagnostics.displacement_code_local_steps,
                   law.linearise_at(u));
        CondensedStep path(r.system, linear_solver, &r.partition, &law);
        path.solve(std::vector<bool>(nq, false),
                   std::vector<double>(nq, 0.),
                   std::vector<double>(nq, 1.),
                   p);
        path.displacements(w, next);
        ++r.diagnostics.displacement_code_steps;
        const double scale = next.linfty_norm();
        changes.push_back(scale > 0 ? largest_difference(next, u) / scale : 0.);
        log << "  displacement code, Newton step "
            << r.diagnostics.displacement_code_steps << ": displacement change "
            << std::scientific << std::setprecision(2) << changes.back()
            << std::defaultfloat << std::setprecision(6) << std::endl;
        u.copy_locally_owned_data_from(next);
        if (!is_complete(u))
          u.update_ghost_values();
      }
    r.diagnostics.displacement_code_seconds = timer.wall_time();
    r.diagnostics.displacement_code_difference =
      largest_difference(u, r.displacement) /
      std::max(r.displacement.linfty_norm(), 1e-300);
    log << "  displacement code: " << r.diagnostics.displacement_code_steps
        << " Newton steps, at most "
        << r.diagnostics.displacement_code_local_steps
        << " local steps to invert the law at a Gauss point, "
        << r.diagnostics.displacement_code_seconds
        << " s (the stress code's solve " << r.solve.seconds
        << " s); displacements differ by " << std::scientific
        << std::setprecision(3) << r.diagnostics.displacement_code_difference
        << std::defaultfloat << std::setprecision(6) << " of the largest"
        << std::endl;
  }

  template class DisplacementCodeComparison<2>;
  template class DisplacementCodeComparison<3>;
} // namespace hrcontact
