#ifndef hrcontact_results_h
#define hrcontact_results_h

#include <deal.II/grid/tria.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/path_choice.h>
#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/postprocess/summary.h>
#include <hrcontact/solvers/contact_iteration.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <array>
#include <string>
#include <vector>

namespace hrcontact
{
  class EquilibriumReduction;
  template <int dim>
  class StressConstraintField;

  /**
   * What a run leaves behind, read-only for postprocessors and tests
   * (HRProblem::results()): the scene and spaces it solved on, the rows of
   * the equilibrium system (eq. 38), the fields, and per stage what it
   * produced: the reactions, the solve on its path, the contact iteration's
   * table and history, the nested levels, the material and stress
   * constraint iterations, the diagnostics; and the summary. Postprocessors add
   * to the summary only; nothing here is changed after the solve.
   */
  template <int dim>
  struct Results
  {
    Results(const Scene<dim>        &scene,
            const MixedSpaces<dim>  &spaces,
            const EquilibriumSystem &system,
            const DofPartition      &partition)
      : scene(scene)
      , spaces(spaces)
      , system(system)
      , partition(partition)
    {}

    const Scene<dim>        &scene;
    const MixedSpaces<dim>  &spaces;
    const EquilibriumSystem &system;
    const DofPartition      &partition;

    /** The mesh: on several processes a
     * parallel::distributed::Triangulation, whose n_active_cells() counts
     * only this process's own, ghost and artificial cells
     * (n_global_active_cells() counts the mesh). */
    const dealii::Triangulation<dim> &
    triangulation() const
    {
      return spaces.dof_handler_displacement.get_triangulation();
    }

    /**
     * The stresses s (stress dofs, the mesh's numbering): on a distributed
     * mesh only this process's own and ghost cells' entries (FieldVector);
     * complete on a serial mesh.
     */
    FieldVector stress;
    /**
     * The stress element's parameters (Pian-Sumihara's beta per cell,
     * numbered by MixedSpaces::stress_unknowns()), on which the equilibrium
     * rows act; empty for a nodal element, whose unknowns are `stress`.
     */
    FieldVector stress_parameters;
    /** What EquilibriumSystem's rows multiply (C s, Q s, H s). */
    const FieldVector &
    stress_unknowns() const
    {
      return stress_parameters.size() ? stress_parameters : stress;
    }
    /** The displacements u (eq. 51), the mesh's numbering: on a
     * distributed mesh the owned and ghost (locally relevant) dofs; complete
     * on a serial mesh. */
    FieldVector displacement;
    /** What recover_fields and row_reactions leave: the reactions of the
     * rows and the contact nodes' displacements. */
    struct Reactions
    {
      /** The displacement of the node of each Q row (its first dim dofs'
       * components, complete on every process: contact.csv). */
      std::vector<std::array<double, 3>> contact_node_displacement;
      /** Normal displacement w_n per Q row (g + mu after the last
       * update). */
      std::vector<double> contact_w;
      /** p = Q s - q per Q row; r = H s - f_H per prescribed (H) row. */
      std::vector<double> contact, support;
    };
    Reactions reactions;

    /** True when the scene has unilateral contact or constraint laws. */
    bool has_contact = false;
    /** Rigid-body motions only the unilateral contacts hold. */
    unsigned int free_rigid_motions = 0;
    /** The augmented Lagrangian's final state, history and outcome; null
     * without contact. */
    const ContactIteration *contact = nullptr;
    /** The contact iteration converged (always true without contact). */
    bool
    converged() const
    {
      return !contact || contact->converged();
    }

    /** The solve on its path (PathChoice, ContactSolve). */
    struct Solve
    {
      /** The path the run took. */
      SolutionPath path = SolutionPath::null_space;
      /** The dense reduction (null-space path only, else null). */
      const EquilibriumReduction *reduction = nullptr;
      /** Counters of the condensed path's linear solves (zero
       * otherwise). */
      LinearSolverStatistics linear_statistics;
      /** The mesh's largest cell aspect ratio (largest_cell_aspect_ratio);
       * it selects the AMG aggregation (Linear solver/AMG aggregation =
       * automatic). */
      double largest_aspect_ratio = 1;
      /** Wall time of building the Newton-step path and the contact
       * iteration (or the one solve without contact). */
      double seconds = 0;
    };
    Solve solve;
    /** The diagnostics a scene asks for under Output/ (diagnostics/). */
    struct Diagnostics
    {
      /** Output/Time the Q1 floor (Q1Floor): wall time and CG iterations of
       * the plain Q1 displacement solve of the same mesh and supports, and
       * its displacements (empty when not timed). */
      double       floor_seconds    = 0;
      unsigned int floor_iterations = 0;
      FieldVector  floor_displacement;
      /** Output/Time a linear elastic solve (ElasticTiming). */
      double linear_elastic_seconds = 0;
      /**
       * Output/Compare with a displacement code (DisplacementCodeComparison):
       * its Newton steps, the largest number of local steps a Gauss point's
       * inversion of the law took, its wall time, and max |u_displacement
       * code - u| / max |u| (steps 0 when not compared).
       */
      unsigned int displacement_code_steps       = 0;
      unsigned int displacement_code_local_steps = 0;
      double       displacement_code_seconds     = 0;
      double       displacement_code_difference  = 0;
    };
    Diagnostics diagnostics;
    /**
     * The coarser levels the nested iteration solved first (coarsest
     * first; empty without nested iteration). Their time is part of
     * solve.seconds.
     */
    struct CoarseLevel
    {
      unsigned int global_refinements = 0, displacement_dofs = 0, updates = 0,
                   newton_steps = 0, linear_solves = 0, material_steps = 0;
      bool converged = false;
      /** The level's own wall time, without the coarser levels before it
       * (so that the levels' seconds add up). */
      double seconds = 0;
    };
    std::vector<CoarseLevel> coarse_levels;
    /** A nonlinear material law (MaterialIteration): the Newton steps it
     * took, each one linear solve, and the relative stress change after
     * each step but the first (empty for a linear law). */
    struct Material
    {
      unsigned int        newton_steps = 0;
      std::vector<double> changes;
    };
    Material material;
    /**
     * A stress constraint (Material/Admissible stresses,
     * StressConstraintIteration): the multiplier updates, the relative
     * residual after each, the material Newton steps of each inner solve,
     * the area (volume) fraction of cracked constraint points, the largest
     * fracture strain, and the state itself (for output), null without one.
     */
    struct StressConstraintState
    {
      std::vector<double>               residuals;
      std::vector<unsigned int>         inner_steps;
      double                            cracked_fraction        = 0;
      double                            largest_fracture_strain = 0;
      const StressConstraintField<dim> *field                   = nullptr;
      /** The closed-form projection's converged point strains (in the
       * stress unknowns' DGQ1 space), and the ones its iteration starts
       * from (a coarser level's, prolongated; empty: the elastic step). */
      FieldVector point_strains, start_point_strains;
      /** The interior point's strains at the end of the stage of Carried
       * initial barrier (BarrierPath), and the coarser level's, which a
       * finer level starts over from where the carried answer is far off
       * (empty: none). */
      FieldVector carried_point_strains, start_path_strains;
      /** Whether this level's carried start was rejected (far off the
       * finer path) and the path followed from start_path_strains. */
      bool carried_start_rejected = false;
      /** The barrier's scale: the largest stress of the level's first
       * step, or the coarser level's where the level started over on the
       * path (a finer level's start is judged against it). */
      double elastic_stress = 0;
      /** The Gauss-point method that solved it ("closed-form projection"
       * or "interior point"); empty for the augmented Lagrangian. */
      std::string gauss_point_method;
    };
    StressConstraintState stress_constraint;
    /** Wall time of the run's sections so far (for summary.txt). */
    double wall_time = 0;

    /** summary.txt as the postprocessors have filled it. */
    Summary summary;
  };
} // namespace hrcontact

#endif
