#include <deal.II/base/timer.h>

#include <hrcontact/diagnostics/elastic_timing.h>
#include <hrcontact/solvers/condensed/condensed_step.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  ElasticTiming<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Time a linear elastic solve",
      "false",
      Patterns::Bool(),
      "Benchmarks: before the contact iteration, solve the condensed system "
      "once more with every contact row held at its gap (a linear elastic "
      "problem on the same mesh and processes, from a fresh matrix and "
      "preconditioner) and report its wall time as "
      "linear_elastic_solve_seconds beside contact_solve_seconds in "
      "summary.txt. Condensed path only; costs one extra solve.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ElasticTiming<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    enabled = prm.get_bool("Time a linear elastic solve");
    prm.leave_subsection();
  }

  template <int dim>
  bool
  ElasticTiming<dim>::run(const LinearSolverSettings &linear_solver,
                          Results<dim>               &r,
                          std::ostream               &log) const
  {
    r.diagnostics.linear_elastic_seconds = 0;
    if (!enabled || r.solve.path != SolutionPath::condensed)
      return false;
    // A fresh path, so that nothing is reused from it.
    const unsigned int  nq = r.system.contact_rows.size();
    Timer               timer;
    std::vector<double> p;
    CondensedStep(r.system, linear_solver, &r.partition)
      .solve(std::vector<bool>(nq, false),
             std::vector<double>(nq, 0.),
             std::vector<double>(nq, 1.),
             p);
    r.diagnostics.linear_elastic_seconds = timer.wall_time();
    log << "  one linear elastic solve (contact rows held at their gaps): "
        << r.diagnostics.linear_elastic_seconds << " s" << std::endl;
    return true;
  }

  template class ElasticTiming<2>;
  template class ElasticTiming<3>;
} // namespace hrcontact
