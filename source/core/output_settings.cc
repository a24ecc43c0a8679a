#include <hrcontact/core/output_settings.h>

namespace hrcontact
{
  using namespace dealii;

  void
  OutputSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::Anything(),
                      "Directory for summary.txt and solution.vtu, relative "
                      "to the working directory; created if missing.");
    prm.declare_entry("Print timing",
                      "true",
                      Patterns::Bool(),
                      "Print a table of wall times at the end of the run, "
                      "and the resident memory of the largest process after "
                      "each stage (tests switch it off to keep their output "
                      "reproducible).");
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

  void
  OutputSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory         = prm.get("Output directory");
    print_timing      = prm.get_bool("Print timing");
    time_linear_solve = prm.get_bool("Time a linear elastic solve");
    time_floor        = prm.get_bool("Time the Q1 floor");
    compare_displacement_code =
      prm.get_bool("Compare with a displacement code");
    prm.leave_subsection();
  }
} // namespace hrcontact
