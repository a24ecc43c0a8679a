#ifndef hrcontact_hr_problem_h
#define hrcontact_hr_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <hrcontact/core/memory_log.h>
#include <hrcontact/core/mesh_setup.h>
#include <hrcontact/core/output_settings.h>
#include <hrcontact/core/path_choice.h>
#include <hrcontact/core/results.h>
#include <hrcontact/core/scene.h>
#include <hrcontact/diagnostics/displacement_code_comparison.h>
#include <hrcontact/diagnostics/elastic_timing.h>
#include <hrcontact/diagnostics/q1_floor.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/postprocess/postprocessor.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/material_loop.h>
#include <hrcontact/solvers/nested_level_runner.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <memory>
#include <ostream>
#include <string>

namespace hrcontact
{
  /**
   * One run of a scene, the orchestrator of doc/design.md: it builds the
   * stages from the parameters and runs them in order (mesh, rows, path,
   * diagnostics, coarser levels, contact solve, fields, output). Each stage
   * is a class of its own; this one computes nothing itself. Its state is
   * private; what it computed is read through results().
   */
  template <int dim>
  class HRProblem
  {
  public:
    /** Declare every parameter a run reads (all dimensions alike). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * A run on the processes of the communicator (MeshSetup says when the
     * mesh is distributed). Process 0 writes the result files and each
     * process its piece of solution.pvtu. `as_coarser_level`: this run is
     * a coarser level of the nested iteration (NestedLevelRunner).
     */
    explicit HRProblem(dealii::ParameterHandler  &prm,
                       const MPI_Comm             communicator = MPI_COMM_WORLD,
                       const CoarserLevelRequest *as_coarser_level = nullptr);

    /**
     * An adaptive cycle (run_adaptive_cycles): the mesh replays the steps
     * of the cycles before (call before solve()), and summary.txt lists
     * their records (call again before output_results()). The contact
     * iteration and CG start from @p previous_cycle's answer, if given (it
     * must outlive solve()).
     */
    void
    refine_adaptively(const AdaptiveRefinement<dim> &cycles,
                      const HRProblem<dim>          *previous_cycle = nullptr);

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

    /** Why the contact iteration did not converge, and what to change;
     * empty when it converged. */
    std::string
    outcome_message() const;

  private:
    /** Mesh, spaces, partition and the row classification. */
    void
    setup(std::ostream &log);
    /** The path: the dense reduction or the condensed system. */
    std::unique_ptr<NewtonStepPath>
    build_path(std::ostream &log);

    MPI_Comm mpi_communicator;
    /** A coarser level of the nested iteration: its polygonal mesh may miss
     * a probe on a curved boundary, and it writes no results. */
    bool coarser_level = false;
    /** Declared before the spaces, whose DoFHandlers refer to its mesh. */
    MeshSetup<dim>                  mesh;
    Scene<dim>                      scene;
    MixedSpaces<dim>                spaces;
    PathChoice                      path_choice;
    EquilibriumReduction            reduction;
    LinearSolverSettings            linear_solver;
    AugmentedLagrangianSolver       contact_solver;
    PostprocessorManager<dim>       postprocessors;
    OutputSettings                  output;
    NestedLevelRunner<dim>          nested;
    MaterialLoop<dim>               material_loop;
    Q1Floor<dim>                    floor;
    ElasticTiming<dim>              elastic_timing;
    DisplacementCodeComparison<dim> displacement_code;
    EquilibriumSystem               system;
    /** The p4est partition of the displacement dofs and cells. */
    DofPartition partition;
    /** The coarser level's displacements on this mesh (nested iteration
     * with CG): the first solve starts from them instead of zero. */
    FieldVector         coarse_start;
    Results<dim>        results_;
    dealii::TimerOutput timer;
    MemoryLog           memory;
  };
} // namespace hrcontact

#endif
