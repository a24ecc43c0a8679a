#ifndef hrcontact_hr_problem_h
#define hrcontact_hr_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/postprocess/postprocessor.h>
#include <hrcontact/solvers/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/newton_step.h>

#include <functional>
#include <ostream>
#include <string>

namespace hrcontact
{
  /** Where results go and how chatty a run is. */
  struct OutputSettings
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** 2D contact postprocessing (see declare_parameters). */
    std::string hertz_load, hertz_radius, tracked_nodes;
    /** tunnel_lining postprocessing (see declare_parameters). */
    unsigned int lining_sections = 120;
    std::string  lining_reference_principal_stresses;

    std::string directory    = "output";
    bool        write_vtu    = true;
    bool        print_timing = true;
    /** Benchmarks: time one linear elastic solve (see declare_parameters). */
    bool time_linear_solve = false;
  };

  /**
   * A linear elastic run with bilateral supports: mesh, spaces, HR blocks,
   * equilibrium reduction, maximisation of the complementary energy,
   * displacements (eq. 51), postprocessing. The pieces stay accessible so
   * that tests can check identities on them.
   */
  template <int dim>
  class HRProblem
  {
  public:
    /** Declare every parameter a run reads (all dimensions alike). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * A run on the processes of the communicator: the mesh, the HR blocks
     * and the contact iteration are replicated; with several processes the
     * condensed path's linear algebra is distributed by a p4est partition,
     * process 0 writes the result files and each process its piece of
     * solution.pvtu.
     */
    explicit HRProblem(dealii::ParameterHandler &prm,
                       const MPI_Comm            communicator = MPI_COMM_WORLD);

    /** Everything up to and including the solve; no files written. */
    void
    solve(std::ostream &log);

    /** Postprocess and write summary.txt (and solution.vtu). */
    void
    output_results(std::ostream &log);

    /** solve() then output_results(). */
    void
    run(std::ostream &log);

    Scene<dim>           scene;
    MixedSpaces<dim>     spaces;
    EquilibriumReduction reduction;
    LinearSolverSettings linear_solver;
    /** Counters of the condensed path's linear solves (zero otherwise). */
    LinearSolverStatistics     linear_statistics;
    AugmentedLagrangianSolver  contact_solver;
    Postprocessor<dim>         postprocessor;
    OutputSettings             output;
    dealii::Triangulation<dim> triangulation;
    EquilibriumSystem          system;
    MPI_Comm                   mpi_communicator;
    /** The p4est partition of the displacement dofs and cells. */
    DofPartition partition;

    dealii::Vector<double> stress;
    dealii::Vector<double> displacement;
    /** "null-space" or "condensed": the path the run took. */
    std::string solution_path;
    /**
     * Wall time of building the Newton-step path and the contact iteration
     * (or the one solve without contact), and of one linear elastic solve
     * when Output/Time a linear elastic solve is set.
     */
    double contact_solve_seconds = 0, linear_elastic_seconds = 0;
    /** True when the scene has unilateral contact constraints. */
    bool has_contact = false;
    /** Rigid-body motions only the unilateral contacts hold. */
    unsigned int free_rigid_motions = 0;
    /** Normal displacement w_n per Q row (g + mu after the last update). */
    std::vector<double> contact_w;
    /** p = Q s - q per contact row; r = H s - f_H per prescribed row. */
    std::vector<double> contact_reactions, support_reactions;
    Summary             summary;

  private:
    /** A sentence for stop messages when contacts alone hold the body. */
    std::string
    mechanism_hint() const;
    void
    write_contact_tables() const;
    /** Pressures from nodal reactions, contact zone, Hertz comparison. */
    void
    contact_pressure_summary(std::ostream &log);
    /**
     * tunnel_lining scenes: section forces (lining.csv), contact pressure
     * along the extrados (lining-contact.csv), pressed zones, extremes of
     * the principal stresses and of N and M in summary.txt.
     */
    void
    lining_output(std::ostream &log);
    /** Indices of the selected Q rows, sorted by x, then y, then z. */
    std::vector<unsigned int>
    sorted_q_rows(
      const std::function<bool(const EquilibriumRow &)> &select) const;
    /** Sorted unilateral Q-row indices (by x, then y, then z). */
    std::vector<unsigned int>
    sorted_contact_rows() const;
    /** Indices of the two-sided stop rows among the Q rows, sorted by node
     * coordinates. */
    std::vector<unsigned int>
    sorted_stop_rows() const;
    /**
     * Contact/Update curved obstacles: re-linearise the curved obstacles at
     * the current configuration of the path's last solve; whether a row
     * changed.
     */
    bool
    relinearise_curved_obstacles(const NewtonStepPath &path);

    dealii::TimerOutput timer;
    std::string         parameter_file_name;
  };
} // namespace hrcontact

#endif
