#include <hrcontact/core/input.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  std::string
  to_string(const LinearSolverKind kind)
  {
    return kind == LinearSolverKind::direct ? "direct" : "cg-amg";
  }

  void
  LinearSolverSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
      "Solver",
      "automatic",
      Patterns::Selection("automatic|direct|cg-amg"),
      "Condensed path only: how each Newton step's sparse SPD system is "
      "solved. direct: UMFPACK (exact, memory grows fast in 3D), or MUMPS "
      "under mpirun (as a symmetric positive definite matrix, its analysis "
      "kept while the pattern is); cg-amg: CG preconditioned by "
      "Trilinos ML smoothed-aggregation AMG with the rigid-body modes as near "
      "null space, distributed over the processes under mpirun; automatic: "
      "direct up to Direct solver limit unknowns (per dimension), cg-amg "
      "above; in 2D with Material/Admissible stresses direct at any size "
      "(CG slows down as the constraint's penalty grows).");
    prm.declare_entry("Direct solver limit 2D",
                      "5e4",
                      Patterns::Double(0),
                      "Unknowns up to which Solver = automatic takes the "
                      "direct solver in 2D (also on each coarser level of "
                      "a nested iteration). Measured (doc/performance.md, "
                      "2026-11-27): the tunnel's contact solve at 5.1e4 "
                      "unknowns 1.05 s with CG + AMG against 1.5 s with "
                      "UMFPACK; Hertz at 9.9e4 as fast either way serially, "
                      "but as a coarser level on 2 processes 1.3-1.6 s "
                      "against 3.8-4.3 s with MUMPS; below 2e4 the direct "
                      "solver wins (Hertz at 6.3e3: 0.53 s against 0.93 s).");
    prm.declare_entry("Direct solver limit 3D",
                      "1e4",
                      Patterns::Double(0),
                      "The same in 3D, where sparse direct factors fill in "
                      "much faster: CG + AMG is 6 times faster and needs 2.4 "
                      "times less memory on the 3D block at 5.6e4 unknowns.");
    prm.declare_entry(
      "Tolerance",
      "1e-12",
      Patterns::Double(0, 1),
      "CG stops when the residual falls below this fraction of the right-hand "
      "side's norm. The contact reactions p = Q s - q are differences of "
      "large nodal forces, so keep it tight (1e-12 gives p to about 1e-9). "
      "When the contact iteration shows the noise of looser solves (an inner "
      "Newton cycle, an inner iteration at Maximum Newton steps, ||pbar|| "
      "doubling at an update with no status change), the run divides this by 100 (down to "
      "1e-15) and goes on, and says so in the log and in summary.txt "
      "(linear_tolerance, linear_tolerance_tightenings).");
    prm.declare_entry("Maximum iterations",
                      "2000",
                      Patterns::Integer(1),
                      "CG iterations per solve before the run stops with a "
                      "named error (exit code 3).");
    prm.declare_entry(
      "Reuse preconditioner",
      "automatic",
      Patterns::Selection("automatic|true|false"),
      "Keep the AMG hierarchy of an earlier Newton step while CG still "
      "converges in at most twice the iterations it took right after the "
      "set-up plus 5 (the matrices differ only in the contact rows); rebuild "
      "it otherwise (a step with the last step's held rows and springs, "
      "which changes only the right-hand side, keeps it in any case). "
      "automatic: keep it in 3D, where one set-up costs about "
      "two floors' worth of CG iterations (3D block at 807k dofs on 2 "
      "processes: contact solve 202 s rebuilding, 160 s keeping), and in 2D "
      "on a level that starts from a coarser level's state (Nested "
      "iteration), whose Newton steps switch a few rows (Hertz refinement 9 "
      "on 2 processes: one row, 4 more CG iterations instead of a 4-5 s "
      "set-up; 2.3-2.8 floors in medians of 3 instead of 3.0); rebuild it in "
      "2D otherwise, where "
      "steps switch many rows and a kept hierarchy preconditions poorly (the "
      "tunnel: 300 CG iterations instead of 18; doc/performance.md).");
    prm.declare_entry(
      "AMG aggregation threshold",
      "0",
      Patterns::Double(0, 1),
      "ML's aggregation threshold: matrix entries below this fraction of the "
      "diagonal do not connect nodes when the aggregates are built. Larger "
      "values coarsen less across weak couplings. 0 is ML's own default. "
      "deal.II's 1e-4, the default before 2026-11-27, cost the 3D block at "
      "807k dofs 20 CG iterations instead of 17 and an AMG set-up of 12.5 s "
      "instead of 10.0 s; on the tunnel and on Hertz (aggregated by "
      "coordinates) the iterations differ by at most 3 % "
      "(doc/performance.md).");
    prm.declare_entry(
      "AMG aggregation",
      "automatic",
      Patterns::Selection("automatic|matrix|coordinates"),
      "How ML groups the nodes into aggregates. matrix: along the matrix "
      "graph, entries below AMG aggregation threshold dropped (ML's "
      "default); coordinates: along a distance Laplacian of the node "
      "coordinates (ML's auxiliary aggregation), entries below AMG "
      "coordinate threshold dropped, so that aggregates follow stretched "
      "cells; automatic: coordinates where the mesh has a cell of aspect "
      "ratio above AMG aspect ratio limit, matrix otherwise. Measured "
      "(doc/performance.md): on the graded Hertz mesh (largest aspect ratio "
      "102 and 145 at refinements 7 and 8) the Q1 floor takes 49, 60, 80 CG "
      "iterations instead of 168, 207, 251, in half the time; on the tunnel "
      "(2.6) coordinates gain nothing and on the 3D block (1) they double "
      "the iterations.");
    prm.declare_entry("AMG coordinate threshold",
                      "0.03",
                      Patterns::Double(0, 1),
                      "With coordinate aggregation: distance-Laplacian "
                      "entries below this fraction of the diagonal do not "
                      "connect nodes (Hertz refinement 7: 58, 53, 49, 49, "
                      "220 CG iterations at 0.01, 0.02, 0.03, 0.05, 0.1).");
    prm.declare_entry("AMG aspect ratio limit",
                      "4",
                      Patterns::Double(1),
                      "AMG aggregation = automatic takes the coordinates "
                      "when the mesh's largest cell aspect ratio exceeds "
                      "this (per cell, the largest singular value of the "
                      "cell map's Jacobian at the centre over the smallest; "
                      "a x b rectangles: a / b; Hertz 50-145 at refinements "
                      "5-8, tunnel 2.6, boxes 1).");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Patterns::Integer(1, 20),
                      "Degree of the Chebyshev smoother on each AMG level.");
    prm.declare_entry("Warm start",
                      "true",
                      Patterns::Bool(),
                      "Start CG from the previous Newton step's displacements "
                      "instead of zero.");
    prm.declare_entry(
      "Warm start reduction",
      "1e-6",
      Patterns::Double(0, 1),
      "A warm-started CG stops at Tolerance of the right-hand side or at "
      "this fraction of its initial residual, whichever is smaller (never "
      "below 1e-15 of the right-hand side): a step whose right-hand side "
      "changed by less than Tolerance still moves p by its change. "
      "Measured on Hertz refinement 9, 2 processes: 1e-6 takes 2 fine "
      "Newton steps and 242 CG iterations (89-91 s); 1e-4 saves iterations "
      "per solve but its noise costs a third Newton step (109 s).");
    prm.leave_subsection();
  }

  void
  LinearSolverSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    solver          = get_selection<Choice>(prm,
                                   "Solver",
                                   {{"automatic", Choice::automatic},
                                             {"direct", Choice::direct},
                                             {"cg-amg", Choice::cg_amg}});
    direct_limit_2d = prm.get_double("Direct solver limit 2D");
    direct_limit_3d = prm.get_double("Direct solver limit 3D");
    tolerance       = prm.get_double("Tolerance");
    max_iterations  = prm.get_integer("Maximum iterations");
    reuse_preconditioner =
      get_selection<Reuse>(prm,
                           "Reuse preconditioner",
                           {{"automatic", Reuse::automatic},
                            {"true", Reuse::always},
                            {"false", Reuse::never}});
    warm_start            = prm.get_bool("Warm start");
    warm_start_reduction  = prm.get_double("Warm start reduction");
    aggregation_threshold = prm.get_double("AMG aggregation threshold");
    smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
    aggregation =
      get_selection<Aggregation>(prm,
                                 "AMG aggregation",
                                 {{"automatic", Aggregation::automatic},
                                  {"matrix", Aggregation::matrix},
                                  {"coordinates", Aggregation::coordinates}});
    coordinate_threshold = prm.get_double("AMG coordinate threshold");
    aspect_ratio_limit   = prm.get_double("AMG aspect ratio limit");
    prm.leave_subsection();
  }

  bool
  LinearSolverSettings::aggregates_by_coordinates() const
  {
    return aggregation == Aggregation::coordinates ||
           (aggregation == Aggregation::automatic &&
            largest_aspect_ratio > aspect_ratio_limit);
  }

  bool
  LinearSolverSettings::reuses_preconditioner(const unsigned int dim) const
  {
    return reuse_preconditioner == Reuse::always ||
           (reuse_preconditioner == Reuse::automatic &&
            (dim == 3 || starts_from_coarser_level));
  }

  LinearSolverKind
  LinearSolverSettings::choose(const unsigned int n,
                               const unsigned int dim) const
  {
    if (solver != Choice::automatic)
      return solver == Choice::direct ? LinearSolverKind::direct :
                                        LinearSolverKind::cg_amg;
    if (stiffening_compliance && dim == 2)
      return LinearSolverKind::direct;
    return (n <= (dim == 3 ? direct_limit_3d : direct_limit_2d)) ?
             LinearSolverKind::direct :
             LinearSolverKind::cg_amg;
  }

  void
  log_linear_statistics(const LinearSolverStatistics &s,
                        const double                  largest_aspect_ratio,
                        const bool                    print_timing,
                        std::ostream                 &log)
  {
    log << "  linear solver: " << s.solver << ", " << s.solves << " solves"
        << (s.iterative ?
              ", " + std::to_string(s.iterations) + " CG iterations, " +
                std::to_string(s.preconditioner_setups) +
                " AMG set-ups, aggregates by " + s.aggregation +
                " (largest cell aspect ratio " +
                std::to_string(int(std::round(largest_aspect_ratio))) + ")" :
              std::string());
    if (print_timing)
      log << " (set-ups " << s.setup_seconds << " s, solves " << s.solve_seconds
          << " s)";
    if (s.tightenings > 0)
      log << ", tolerance tightened " << s.tightenings << " time(s) to "
          << s.tolerance;
    log << std::endl;
  }
} // namespace hrcontact
