#ifndef hrcontact_linear_solver_settings_h
#define hrcontact_linear_solver_settings_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace hrcontact
{
  /** The linear solver of a condensed path's systems. */
  enum class LinearSolverKind
  {
    /** UMFPACK serially, MUMPS (MumpsFactor) under MPI. */
    direct,
    /** CG preconditioned by Trilinos ML AMG with the rigid-body modes. */
    cg_amg
  };

  /** "direct" or "cg-amg", as the logs and summary.txt write it. */
  std::string
  to_string(const LinearSolverKind kind);

  /**
   * How the condensed path solves its sparse SPD systems: a sparse direct
   * solver (UMFPACK), or CG preconditioned by Trilinos ML smoothed-aggregation
   * AMG that is given the rigid-body modes of elasticity (translations and
   * rotations) as its near null space. The AMG hierarchy is kept across
   * Newton steps while it still converges quickly, and CG starts from the
   * previous step's displacements.
   */
  struct LinearSolverSettings
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Linear solver/Solver. */
    enum class Choice
    {
      automatic,
      direct,
      cg_amg
    };
    /** Linear solver/Reuse preconditioner. */
    enum class Reuse
    {
      automatic,
      always,
      never
    };
    /** Linear solver/AMG aggregation. */
    enum class Aggregation
    {
      automatic,
      matrix,
      coordinates
    };

    /**
     * The solver for a system with n unknowns in dim dimensions.
     * With stiffening_compliance, automatic takes direct at any size in 2D:
     * CG's iterations grow with a stress constraint's penalty (the no-tension
     * pier at 198k dofs on 2 processes: as fast as MUMPS at alpha E = 100,
     * 2.2 times slower at 1e3; doc/materials.md).
     */
    LinearSolverKind
    choose(const unsigned int n, const unsigned int dim) const;
    /** Whether the AMG hierarchy is kept across Newton steps in dim. */
    bool
    reuses_preconditioner(const unsigned int dim) const;

    Choice solver          = Choice::automatic;
    double direct_limit_2d = 5e4;
    double direct_limit_3d = 1e4;
    /** Cell compliances that grow by orders of magnitude during the solve
     * (a stress constraint's penalty); set by the problem, not a parameter. */
    bool         stiffening_compliance = false;
    double       tolerance             = 1e-12;
    unsigned int max_iterations        = 2000;
    /** automatic: keep in 3D, and in 2D on a level that starts from a
     * coarser one's state. */
    Reuse reuse_preconditioner = Reuse::automatic;
    /** The contact iteration starts from a coarser level's state (nested
     * iteration), so its Newton steps switch few rows; set by the problem,
     * not a parameter. */
    bool         starts_from_coarser_level = false;
    bool         warm_start                = true;
    double       warm_start_reduction      = 1e-6;
    double       aggregation_threshold     = 0;
    unsigned int smoother_sweeps           = 2;
    Aggregation  aggregation               = Aggregation::automatic;
    double       coordinate_threshold      = 0.03;
    double       aspect_ratio_limit        = 4;
    /** The mesh's largest cell aspect ratio; set by the problem, not a
     * parameter. */
    double largest_aspect_ratio = 1;

    /**
     * Whether ML builds its aggregates from the node coordinates (a distance
     * Laplacian) instead of the matrix graph. On stretched cells the matrix
     * graph of elasticity does not show which couplings are strong, and
     * aggregates that cross the thin direction coarsen what the smoother
     * cannot reach: on the graded Hertz mesh the Q1 floor's CG iterations
     * grow 168, 207, 251 at refinements 7, 8, 9 with the matrix graph and
     * take 49, 60, 80 with the coordinates (doc/performance.md).
     */
    bool
    aggregates_by_coordinates() const;
  };

  /** Counters of the linear solves of a path, for logs and benchmarks. */
  struct LinearSolverStatistics
  {
    /** "direct" or "cg-amg" (empty on the null-space path). */
    std::string solver;
    /** CG + AMG: an iterative solve, with a tolerance of its own. */
    bool         iterative  = false;
    unsigned int solves     = 0;
    unsigned int iterations = 0;
    /** CG iterations of the first solve (a nested level's carried start). */
    unsigned int first_solve_iterations = 0;
    unsigned int preconditioner_setups  = 0;
    /** setup_seconds: UMFPACK and MUMPS factorisations, AMG set-ups and, for
     * the Trilinos back end, the assembly of the distributed matrix
     * (preconditioner_setups counts the factorisations of the direct back
     * ends). solve_seconds: the rest, CG or the substitutions. The two do
     * not overlap (before 2026-11-27 solve_seconds also held the AMG and
     * MUMPS set-ups). */
    double setup_seconds = 0;
    double solve_seconds = 0;
    /** How the AMG aggregates were built, "coordinates" or "matrix"
     * (LinearSolverSettings::aggregates_by_coordinates); empty without AMG. */
    std::string aggregation;
    /** CG's relative tolerance at the end (Linear solver/Tolerance unless an
     * inner Newton cycle tightened it: tighten_linear_solver), and how often
     * it was tightened. */
    double       tolerance   = 0;
    unsigned int tightenings = 0;
  };

  /** The run's log line of its linear solves (condensed path): solver,
   * solves, CG iterations and AMG set-ups, tightenings. */
  void
  log_linear_statistics(const LinearSolverStatistics &statistics,
                        const double                  largest_aspect_ratio,
                        const bool                    print_timing,
                        std::ostream                 &log);
} // namespace hrcontact

#endif
