#include <hrcontact/core/run_summary.h>
#include <hrcontact/solvers/equilibrium_reduction.h>

#include <iomanip>
#include <sstream>

namespace hrcontact
{
  template <int dim>
  void
  RunSummary<dim>::fill(const Results<dim> &r,
                        const bool          elastic_solve_timed,
                        Summary            &summary)
  {
    const EquilibriumSystem &system = r.system;
    summary                         = Summary();
    summary.add("dimension", dim);
    summary.add("plane_condition", r.scene.plane_condition_name());
    summary.add("stress_element", r.spaces.stress_element_name);
    summary.add("cells", r.triangulation().n_global_active_cells());
    summary.add("largest_aspect_ratio", r.solve.largest_aspect_ratio);
    summary.add("displacement_dofs", system.n_displacement_dofs);
    summary.add("stress_dofs", system.n_stress_dofs);
    summary.add("free_rows", system.n_free_rows);
    summary.add("normal_rows", system.contact_rows.size());
    summary.add("prescribed_rows", system.prescribed_rows.size());
    summary.add("solution_path", to_string(r.solve.path));
    if (r.solve.path == SolutionPath::condensed)
      add_linear_solver(r, elastic_solve_timed, summary);
    if (r.solve.reduction)
      summary.add("self_equilibrated_stresses",
                  r.solve.reduction->n_self_equilibrated());
    summary.add("contact_constraints",
                r.contact ? r.contact->p.size() : std::size_t(0));
    summary.add("iterations", r.contact ? r.contact->history.size() : 0);
    summary.add("newton_steps", r.contact ? r.contact->total_newton_steps : 0);
    summary.add("converged", r.converged() ? "true" : "false");
    add_material(r, summary);
    add_coarse_levels(r, summary);
    add_adaptive_cycles(r, summary);
  }

  template <int dim>
  void
  RunSummary<dim>::add_adaptive_cycles(const Results<dim> &r, Summary &summary)
  {
    const auto &cycles = r.scene.adaptive.cycles;
    if (cycles.empty())
      return;
    // One value per cycle, comma-separated, oldest first.
    std::ostringstream cells, dofs, estimates, seconds, solves, carried;
    double             total = 0;
    for (unsigned int k = 0; k < cycles.size(); ++k)
      {
        const char *sep = k ? ", " : "";
        cells << sep << cycles[k].cells;
        dofs << sep << cycles[k].displacement_dofs;
        estimates << sep << std::setprecision(6) << cycles[k].estimate;
        seconds << sep << std::setprecision(4) << cycles[k].seconds;
        solves << sep << cycles[k].linear_solves;
        carried << sep << (cycles[k].carried_start ? 1 : 0);
        total += cycles[k].seconds;
      }
    summary.add("adaptive_cycles", cycles.size() - 1);
    summary.add("adaptive_estimator", r.scene.adaptive.estimator);
    summary.add("adaptive_cycle_cells", cells.str());
    summary.add("adaptive_cycle_dofs", dofs.str());
    summary.add("adaptive_cycle_estimates", estimates.str());
    summary.add("adaptive_cycle_seconds", seconds.str());
    summary.add("adaptive_cycle_linear_solves", solves.str());
    summary.add("adaptive_cycle_carried_start", carried.str());
    summary.add("adaptive_total_seconds", total);
    const AdaptiveRefinement<dim> &adaptive = r.scene.adaptive;
    if (cycles.back().relative_bound >= 0)
      {
        std::ostringstream bounds;
        for (unsigned int k = 0; k < cycles.size(); ++k)
          bounds << (k ? ", " : "") << std::setprecision(6)
                 << cycles[k].relative_bound;
        summary.add("adaptive_cycle_error_bounds", bounds.str());
      }
    if (adaptive.target_error > 0)
      {
        summary.add("target_error", adaptive.target_error);
        summary.add("target_error_reached",
                    cycles.back().relative_bound <= adaptive.target_error ? 1 :
                                                                            0);
      }
  }

  template <int dim>
  void
  RunSummary<dim>::add_linear_solver(const Results<dim> &r,
                                     const bool          elastic_solve_timed,
                                     Summary            &summary)
  {
    const LinearSolverStatistics &s = r.solve.linear_statistics;
    summary.add("linear_solver", s.solver);
    summary.add("linear_solves", s.solves);
    summary.add("linear_iterations", s.iterations);
    summary.add("preconditioner_setups", s.preconditioner_setups);
    if (s.iterative)
      {
        summary.add("linear_tolerance", s.tolerance);
        summary.add("amg_aggregation", s.aggregation);
        summary.add("linear_tolerance_tightenings", s.tightenings);
      }
    summary.add("linear_setup_seconds", s.setup_seconds);
    summary.add("linear_solve_seconds", s.solve_seconds);
    if (elastic_solve_timed)
      summary.add("linear_elastic_solve_seconds",
                  r.diagnostics.linear_elastic_seconds);
  }

  template <int dim>
  void
  RunSummary<dim>::add_material(const Results<dim> &r, Summary &summary)
  {
    if (!r.scene.all_linear() || r.scene.stress_constraint)
      {
        // All levels together, and (nested) each level's, coarsest first.
        unsigned int steps = r.material.newton_steps;
        std::string  per_level;
        for (const auto &level : r.coarse_levels)
          {
            steps += level.material_steps;
            per_level += std::to_string(level.material_steps) + " ";
          }
        summary.add("material_newton_steps", steps);
        if (!r.coarse_levels.empty())
          summary.add("material_newton_steps_per_level",
                      per_level + std::to_string(r.material.newton_steps));
        summary.add("material_stress_change",
                    r.material.changes.empty() ? 0. :
                                                 r.material.changes.back());
      }
    if (!r.scene.stress_constraint)
      return;
    summary.add("stress_constraint", r.scene.stress_constraint->name());
    // The Gauss-point methods have no multiplier updates (their
    // convergence is material_stress_change, the model's stress error).
    if (r.stress_constraint.residuals.empty())
      summary.add("stress_constraint_method",
                  r.stress_constraint.gauss_point_method);
    else
      {
        summary.add("stress_constraint_updates",
                    r.stress_constraint.residuals.size());
        summary.add("stress_constraint_residual",
                    r.stress_constraint.residuals.back());
      }
    summary.add(dim == 2 ? "cracked_area_fraction" : "cracked_volume_fraction",
                r.stress_constraint.cracked_fraction);
    summary.add("largest_fracture_strain",
                r.stress_constraint.largest_fracture_strain);
  }

  template <int dim>
  void
  RunSummary<dim>::add_coarse_levels(const Results<dim> &r, Summary &summary)
  {
    if (r.coarse_levels.empty())
      return;
    unsigned int newton = 0, solves = 0;
    double       seconds = 0;
    for (const auto &level : r.coarse_levels)
      {
        newton += level.newton_steps;
        solves += level.linear_solves;
        seconds += level.seconds;
      }
    summary.add("nested_coarse_levels", r.coarse_levels.size());
    summary.add("coarse_level_newton_steps", newton);
    summary.add("coarse_level_linear_solves", solves);
    summary.add("coarse_level_seconds", seconds);
  }

  template class RunSummary<2>;
  template class RunSummary<3>;
} // namespace hrcontact
