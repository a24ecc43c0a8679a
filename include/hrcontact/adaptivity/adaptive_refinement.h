#ifndef hrcontact_adaptive_refinement_h
#define hrcontact_adaptive_refinement_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/vector.h>

#include <set>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * The cells one adaptive cycle refines and coarsens, by CellId (coarse
   * cell and child path): the same on any partition, so every cycle's mesh
   * is rebuilt from the scene's by replaying the steps, serially and on a
   * distributed mesh alike.
   */
  struct RefinementStep
  {
    std::set<std::string> refine, coarsen;
  };

  /** What one adaptive cycle solved, for the log and summary.txt. */
  struct AdaptiveCycle
  {
    unsigned int cells = 0, displacement_dofs = 0;
    double       seconds = 0;
    /** sqrt(sum of the squared cell indicators). */
    double estimate = 0;
    /** The guaranteed relative error bound (Estimator = bound or a Target
     * error), or -1. */
    double relative_bound = -1;
    /** The linear solves of the contact iteration on this cycle's mesh
     * (nested iteration's coarser levels not counted). */
    unsigned int linear_solves = 0;
    /** Whether it started from the previous cycle's state (Carry state). */
    bool carried_start = false;
  };

  /**
   * `Mesh refinement/`: adaptive cycles (solve, estimate, mark, refine),
   * the estimator, the fixed fractions of cells refined and coarsened
   * (step-42's refine_and_coarsen_fixed_number over the whole mesh) and a
   * ceiling on the dofs; the refinement history the cycles build.
   */
  template <int dim>
  class AdaptiveRefinement
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Whether the run refines adaptively. */
    bool
    active() const
    {
      return n_cycles > 0;
    }

    unsigned int n_cycles         = 0;
    std::string  estimator        = "kelly";
    double       refine_fraction  = 0.3;
    double       coarsen_fraction = 0.03;
    /** Marking = fixed fraction (Doerfler) rather than fixed number. */
    bool fixed_fraction = false;
    /** Each cycle starts from the previous cycle's contact state and
     * displacements (Carry state). */
    bool carry_state = true;
    /** 0: no ceiling. */
    unsigned int maximum_dofs = 0;
    /** Stop once the guaranteed relative error bound is at or below this
     * (0: no target). */
    double target_error = 0;

    /** The steps of the cycles so far, replayed by apply(). */
    std::vector<RefinementStep> history;
    /** The cycles solved so far. */
    std::vector<AdaptiveCycle> cycles;

    /**
     * Replay the history on a mesh: each step flags the active cells this
     * process owns by their ids, then refines. A cell a step names that the
     * mesh does not have (a coarser level of the nested iteration) is
     * skipped; nothing is coarsened below @p coarsest_level.
     */
    void
    apply(dealii::Triangulation<dim> &triangulation,
          const unsigned int          coarsest_level) const;

    /**
     * The step of this cycle: the refine_fraction of all cells with the
     * largest indicators, the coarsen_fraction with the smallest (the
     * thresholds over every process's cells, so the marks do not depend on
     * the partition), their ids gathered on every process.
     */
    RefinementStep
    mark(const dealii::Triangulation<dim> &triangulation,
         const dealii::Vector<float>      &indicators,
         const MPI_Comm                    communicator) const;
  };
} // namespace hrcontact

#endif
