#ifndef hrcontact_hr_problem_h
#define hrcontact_hr_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/output_settings.h>
#include <hrcontact/core/results.h>
#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/discretisation/stress_constraint_field.h>
#include <hrcontact/postprocess/postprocessor.h>
#include <hrcontact/solvers/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/material_iteration.h>
#include <hrcontact/solvers/nested_iteration.h>
#include <hrcontact/solvers/newton_step.h>
#include <hrcontact/solvers/stress_constraint_iteration.h>

#include <memory>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace hrcontact
{
  /**
   * One run of a scene, the orchestrator of doc/design.md: it builds the
   * pieces from the parameters (scene, spaces, equilibrium system, Newton-step
   * path, augmented Lagrangian solver, postprocessors) and runs them in
   * order. Its state is private; what it computed is read through
   * results().
   */
  template <int dim>
  class HRProblem
  {
  public:
    /** Declare every parameter a run reads (all dimensions alike). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * A run on the processes of the communicator. With several processes
     * the condensed path runs on a parallel::distributed::Triangulation:
     * each process assembles and solves for its own cells and runs the
     * augmented Lagrangian on the contact rows of its own and ghost nodes
     * (ContactRowPartition); the rows themselves (a surface) are classified
     * alike on every process, and the final contact state is gathered for
     * the results. Process 0 writes the result files and each process its
     * piece of solution.pvtu. The dense null-space path (the serial reference,
     * which Path = automatic takes for small meshes), a randomly distorted mesh
     * and the tunnel lining's section forces keep a replicated serial mesh.
     */
    explicit HRProblem(dealii::ParameterHandler &prm,
                       const MPI_Comm            communicator = MPI_COMM_WORLD);

    /** Everything up to and including the solve; no files written. */
    void
    solve(std::ostream &log);

    /** Run the postprocessors and write summary.txt. */
    void
    output_results(std::ostream &log);

    /**
     * solve() then output_results(); a contact iteration that did not
     * converge throws NotConvergedError naming the cause, after every file
     * was written.
     */
    void
    run(std::ostream &log);

    /** What the run computed (complete after solve(); the summary after
     * output_results()). */
    const Results<dim> &
    results() const;

  private:
    /** Mesh, spaces, partition and the row classification. */
    void
    setup(std::ostream &log);
    /** "null-space" or "condensed", from the parameters and the size. */
    std::string
    choose_path(std::ostream &log) const;

    /** Whether Path = automatic takes the condensed path whatever the size:
     * a nonlinear material or a stress constraint (a material iteration of
     * many Newton steps, each a dense solve on the null-space path). */
    bool
    material_iteration_prefers_condensed() const;
    /** Bytes of the dense null-space reduction with this many free rows. */
    double
    dense_reduction_bytes(const double n_free_rows) const;
    /** Output/Time the Q1 floor: the plain Q1 displacement solve. */
    void
    time_floor(std::ostream &log);
    /** Output/Compare with a displacement code (DisplacementLawStiffness),
     * after the run's own solve. */
    void
    compare_displacement_code(std::ostream &log);
    /**
     * Nested iteration (NestedIterationSettings): solve the scene with one
     * global refinement fewer (itself nested further as asked), record its
     * levels and hand its converged state to the contact solver. Nothing
     * when no coarser level is asked for; a coarser level that fails is
     * reported and the fine level starts from the trial solution.
     */
    void
    start_from_coarser_level(const std::string &path_name, std::ostream &log);
    /** The contact iteration (or the one solve without contact). */
    void
    solve_on_path(NewtonStepPath &path, std::ostream &log);
    /**
     * Runs `solve_once` (one linear or contact solve at the current
     * linearisation) as the scene's material needs: once for a linear law;
     * under the material Newton iteration for a nonlinear one; under the
     * stress constraint's augmented Lagrangian, each inner solve a material
     * iteration, for Material/Admissible stresses.
     */
    void
    solve_material(NewtonStepPath              &path,
                   const std::function<void()> &solve_once,
                   std::ostream                &log);
    /** Stresses, displacements and reactions from the path's last solve. */
    void
    collect_fields(const NewtonStepPath &path);
    /** The run's own summary.txt keys: dimensions, path, iterations. */
    void
    summarise_run();
    /**
     * Record the resident memory of the largest process after a stage, for
     * the table printed with Output/Print timing (where the memory of a run
     * goes, the figure issue 17's distributed data path is about).
     */
    void
    mark_memory(const std::string &stage);

    MPI_Comm mpi_communicator;
    /**
     * The parameters as read, for the coarser levels of the nested
     * iteration (a copy: the handler need not outlive the constructor).
     */
    std::string parameter_text;
    /**
     * The mesh: a parallel::distributed::Triangulation when several
     * processes run the condensed path (each keeps its own cells, a layer of
     * ghost cells and the coarse mesh), else a serial one. Declared before
     * the spaces, whose DoFHandlers refer to it.
     */
    std::unique_ptr<dealii::Triangulation<dim>> triangulation;
    /** Whether `triangulation` is the distributed one, and what keeps it
     * serial on several processes. */
    bool                      distributed_mesh = false;
    std::string               replicated_mesh_reason;
    Scene<dim>                scene;
    MixedSpaces<dim>          spaces;
    EquilibriumReduction      reduction;
    LinearSolverSettings      linear_solver;
    AugmentedLagrangianSolver contact_solver;
    PostprocessorManager<dim> postprocessors;
    OutputSettings            output;
    NestedIterationSettings   nested;
    /** false for the coarser levels nested iteration solves first: only
     * those measure how the tolerance's force scale shrinks per level (a
     * trial solve of their own), the scene's mesh never pays for it. */
    bool finest_level = true;
    /** Newton's method on a nonlinear law's complementary energy (unused
     * for a linear one). */
    MaterialIteration material_iteration;
    /** The augmented Lagrangian of Material/Admissible stresses, and its
     * multipliers (null without a constraint). */
    StressConstraintIteration                   constraint_iteration;
    std::unique_ptr<StressConstraintField<dim>> constraint_field;
    EquilibriumSystem                           system;
    /** The p4est partition of the displacement dofs and cells. */
    DofPartition partition;
    /**
     * The coarser level's displacements on this mesh (nested iteration with
     * CG): the first solve starts from them instead of zero. Emptied once
     * handed to the path.
     */
    FieldVector         coarse_start;
    Results<dim>        results_;
    dealii::TimerOutput timer;
    /** (stage, resident MB of the largest process, peak MB so far). */
    std::vector<std::tuple<std::string, double, double>> memory_marks;
  };
} // namespace hrcontact

#endif
