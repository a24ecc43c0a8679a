#ifndef hrcontact_nested_level_runner_h
#define hrcontact_nested_level_runner_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hrcontact/core/path_choice.h>
#include <hrcontact/core/results.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/linear_solver_settings.h>
#include <hrcontact/solvers/nested_iteration.h>

#include <ostream>
#include <string>

namespace hrcontact
{
  /**
   * What a finer level asks of the coarser level it solves first: the same
   * scene with fewer global refinements, nested further itself, on the same
   * path and processes, to a looser tolerance, without timing extras.
   */
  struct CoarserLevelRequest
  {
    unsigned int global_refinements = 0;
    /** The levels the coarser level solves below itself. */
    unsigned int coarse_levels      = 0;
    SolutionPath path               = SolutionPath::condensed;
    double       relative_tolerance = 1e-5;
  };

  /**
   * The nested iteration's level runner (NestedIterationSettings): solves
   * the scene with one global refinement fewer by an HRProblem of its own
   * (itself nested further as asked), records its levels, and hands its
   * converged state up to this level's contact solver, its displacements to
   * CG's first guess. The coarser level is read through HRProblem's public
   * interface only: results() and outcome_message(). Nothing when no
   * coarser level is asked for; a coarser level that fails is reported and
   * the fine level starts from the trial solution.
   */
  template <int dim>
  class NestedLevelRunner
  {
  public:
    /** Coarser levels run on the processes of `communicator`. */
    explicit NestedLevelRunner(const MPI_Comm communicator);

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /** The settings, and the parameters as read for the coarser levels (a
     * copy: the handler need not outlive the run). */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** This level is a coarser one (no measuring on the scene's mesh). */
    void
    take_request(const CoarserLevelRequest &request);

    /**
     * An adaptive cycle: start from the previous cycle's converged state
     * (carry_contact_state) and displacements instead of coarser levels,
     * where a state carries at all. @p previous must outlive run().
     */
    void
    carry_from(const Results<dim> &previous);

    /**
     * Solve the coarser levels first, when they apply; results gets
     * coarse_levels, the contact solver its start, linear_solver its
     * starts_from_coarser_level and `coarse_start` the coarser level's
     * displacements (CG only; else left empty).
     */
    void
    run(const SolutionPath         path,
        AugmentedLagrangianSolver &contact_solver,
        LinearSolverSettings      &linear_solver,
        Results<dim>              &results,
        FieldVector               &coarse_start,
        std::ostream              &log) const;

    NestedIterationSettings settings;
    /** The scene's stress constraint is imposed in closed form at the
     * Gauss points (MaterialLoop::projects_constraint): its point strains
     * are the state a coarser level carries, with or without contact. */
    bool carries_point_strains = false;

  private:
    /** The coarser level @p coarse's point strains and barrier scales,
     * prolongated to @p results' mesh as its start. */
    void
    carry_point_strains(const Results<dim> &coarse,
                        Results<dim>       &results) const;

    /** Whether the coarser levels' states apply to this run at all: a
     * contact state (carries_state) or the point strains. */
    bool
    nests(const SolutionPath               path,
          const AugmentedLagrangianSolver &contact_solver,
          const Results<dim>              &results) const;
    /** Whether a carried contact state applies to this run: the condensed
     * path, the consistent AL, fixed rows, linear laws and materials. */
    bool
    carries_state(const SolutionPath               path,
                  const AugmentedLagrangianSolver &contact_solver,
                  const Results<dim>              &results) const;
    /** CG's first guess from @p coarse's displacements (CG only). */
    void
    start_displacements(const Results<dim>         &coarse,
                        const SolutionPath          path,
                        const LinearSolverSettings &linear_solver,
                        const Results<dim>         &results,
                        FieldVector                &coarse_start) const;
    /** How many coarser levels this run solves; refuses what cannot be
     * nested. */
    unsigned int
    levels_to_solve(const SolutionPath               path,
                    const AugmentedLagrangianSolver &contact_solver,
                    const Results<dim>              &results) const;

    MPI_Comm    communicator;
    std::string parameter_text;
    /** false for the coarser levels: only those measure how the
     * tolerance's force scale shrinks per level (a trial solve of their
     * own), the scene's mesh never pays for it. */
    bool finest_level = true;
    /** The previous adaptive cycle's results (carry_from), or none. */
    const Results<dim> *previous_cycle = nullptr;
  };
} // namespace hrcontact

#endif
