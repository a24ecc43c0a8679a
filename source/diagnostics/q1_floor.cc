#include <deal.II/base/timer.h>

#include <hrcontact/diagnostics/q1_floor.h>
#include <hrcontact/discretisation/displacement_stiffness.h>
#include <hrcontact/solvers/condensed/condensed_step.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  Q1Floor<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Time the Q1 floor",
      "false",
      Patterns::Bool(),
      "Benchmarks: before the contact iteration, solve the plain Q1 "
      "displacement problem of the same mesh, processes and supports (every "
      "contact row held at its gap), its stiffness assembled from the "
      "displacement bilinear form int eps(u) : C eps(v) (not from the HR "
      "blocks), with CG and the same ML AMG (rigid-body modes) and tolerance "
      "as Linear solver. summary.txt gets q1_floor_seconds (assembly, AMG "
      "set-up and CG), q1_floor_cg_iterations and the ratios "
      "contact_solve_to_floor and, with Time a linear elastic solve, "
      "elastic_solve_to_floor. Needs Material/Model = linear elasticity; "
      "costs one extra solve.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Q1Floor<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    enabled = prm.get_bool("Time the Q1 floor");
    prm.leave_subsection();
  }

  template <int dim>
  bool
  Q1Floor<dim>::run(const LinearSolverSettings &linear_solver,
                    const bool                  print_timing,
                    Results<dim>               &r,
                    std::ostream               &log) const
  {
    if (!enabled)
      return false;
    // The same supports, processes, CG, AMG and tolerance; K from the
    // displacement bilinear form. Timed from assembly to solution.
    const EquilibriumSystem &system = r.system;
    const unsigned int       nq     = system.contact_rows.size();
    LinearSolverSettings     floor  = linear_solver;
    floor.solver                    = LinearSolverSettings::Choice::cg_amg;
    floor.reuse_preconditioner      = LinearSolverSettings::Reuse::never;
    Timer                            timer;
    const DisplacementStiffness<dim> q1(r.scene, r.spaces);
    CondensedStep                    path(system, floor, &r.partition, &q1);
    std::vector<double>              p;
    path.solve(std::vector<bool>(nq, false),
               std::vector<double>(nq, 0.),
               std::vector<double>(nq, 1.),
               p);
    r.diagnostics.floor_seconds    = timer.wall_time();
    r.diagnostics.floor_iterations = path.statistics.iterations;
    reinit_field(r.diagnostics.floor_displacement,
                 r.spaces.dof_handler_displacement);
    path.displacements(system.contact_row_values(),
                       r.diagnostics.floor_displacement);
    log << "  Q1 floor (plain displacement solve, CG + AMG): "
        << r.diagnostics.floor_seconds << " s, "
        << r.diagnostics.floor_iterations << " CG iterations";
    if (print_timing)
      log << " (assembly and AMG set-up " << path.statistics.setup_seconds
          << " s, CG " << path.statistics.solve_seconds << " s)";
    log << std::endl;
    return true;
  }

  template class Q1Floor<2>;
  template class Q1Floor<3>;
} // namespace hrcontact
