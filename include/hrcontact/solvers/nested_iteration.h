#ifndef hrcontact_nested_iteration_h
#define hrcontact_nested_iteration_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/contact_iteration.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * Where the augmented Lagrangian starts instead of the trial solution
   * (Step 0): per Q row a multiplier mu (w_n - g), a compliance alpha and a
   * reaction estimate p that selects the first piece, piece(p, mu, alpha).
   * Any start converges to the same answer (the iteration only needs one
   * exact solve to begin with); a good one saves the updates and Newton
   * steps that discover the pressed set.
   */
  struct ContactStart
  {
    std::vector<double> mu, alpha, p;
    /**
     * The force scale of the relative tolerance (ContactIteration::
     * tolerance_scale, carried at scale_per_level, or the coarser level's
     * own while this level measures it), so that the finer level stops
     * about where it would have from its own trial solution; 0: none.
     */
    double tolerance_scale = 0;
    /**
     * Solve this level's trial once more, before the carried start, to take
     * its reactions as the force scale and their ratio to the coarser
     * level's (tolerance_scale, then) as scale_per_level for the levels
     * above. Set for the first level that starts from a coarser one.
     */
    bool measure_trial_scale = false;
    /** The factor tolerance_scale takes per level (0: unknown yet), and the
     * range a measured one is kept in: the tributary area (reactions of a
     * smooth pressure) to 1 (a concentrated reaction). */
    double scale_per_level = 0, smallest_scale_per_level = 0;
    /** Where the state comes from, for the log line of the solve it starts. */
    std::string origin = "the coarser level's state";
    /** Whether it holds one entry per Q row of a system. */
    bool
    fits(const EquilibriumSystem &system) const
    {
      const std::size_t n = system.contact_rows.size();
      return mu.size() == n && alpha.size() == n && p.size() == n;
    }
  };

  /**
   * The per-row part of transfer_contact_state, for any two meshes of one
   * scene: each row of `fine` takes the average state of the rows of
   * `coarse` of its kind nearest its node (several at one distance: the
   * midpoints of a refinement; a node both meshes have: its own state),
   * the reaction of coarse row j times reaction_scale(i, j), the compliance
   * times compliance_scale(i, j). A row no coarse row matches starts as the
   * trial does, at the largest coarse compliance times
   * `default_compliance_scale`. The tolerance's fields are left to the
   * caller.
   */
  ContactStart
  transfer_rows_by_position(
    const EquilibriumSystem                                 &coarse,
    const ContactIteration                                  &coarse_state,
    const EquilibriumSystem                                 &fine,
    const std::function<double(unsigned int, unsigned int)> &reaction_scale,
    const std::function<double(unsigned int, unsigned int)> &compliance_scale,
    const double default_compliance_scale);

  /**
   * The state a converged contact iteration on a coarser mesh leaves,
   * carried to the Q rows of a finer one by position: each fine row takes
   * the average of the coarse rows of the same kind (obstacle, law,
   * unilateral) nearest to its node (several at the same distance: the
   * midpoints of uniform refinement, so mu is interpolated linearly along
   * the boundary there, and a node that existed on the coarse mesh takes
   * its own state). Nodal reactions scale with the tributary area,
   * `reaction_scale` (2^{1-dim} per level of uniform refinement); the
   * compliance with the nodal compliance, `compliance_scale`. The force
   * scale of the relative tolerance takes the coarser level's measured
   * ContactIteration::scale_per_level; where there is none yet (the coarser
   * level started from its own trial) this level measures it
   * (ContactStart::measure_trial_scale) if `may_measure_scale` (it is not
   * the scene's own mesh), else takes `reaction_scale`: the largest trial
   * reactions sit at the edges of the glued zone, where they shrink more slowly
   * than the tributary area (Hertz: by 0.56-0.63 per level, not 0.5).
   */
  ContactStart
  transfer_contact_state(const EquilibriumSystem &coarse,
                         const ContactIteration  &coarse_state,
                         const EquilibriumSystem &fine,
                         const double             reaction_scale,
                         const double             compliance_scale,
                         const bool               may_measure_scale);

  /**
   * Nested iteration over the levels of uniform refinement: the contact
   * problem is solved on the scene's mesh with fewer global refinements
   * first, its pressed set, multipliers and penalties are carried to the
   * next level (transfer_contact_state), and so on up to the scene's own
   * mesh, where the iteration then only corrects the boundary of the
   * contact zone. Each level costs a quarter (2D) or an eighth (3D) of the
   * next, so the coarse levels together add about a third (a seventh) of a
   * fine solve, and the fine level needs a few solves instead of tens
   * (doc/benchmarks.md). The answer is the fine level's own: the start
   * changes the path of the iteration, not where it ends (to its
   * tolerance).
   */
  struct NestedIterationSettings
  {
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * The number of coarser levels to solve first, given the scene's global
     * refinements and its displacement dofs, for a run whose contact
     * iteration can start from a carried state (`applies`): `Coarse levels`
     * if a number; automatic: none below `Minimum dofs`, else as many as
     * keep the coarsest level at `Coarsest level dofs` or more.
     */
    unsigned int
    levels(const unsigned int global_refinements,
           const double       displacement_dofs,
           const unsigned int dim,
           const bool         applies) const;

    /**
     * The relative tolerance of the augmented Lagrangian on a coarser
     * level, given the scene's own: the looser of the two. A coarser level
     * only carries its state up, and the finest level's first multiplier
     * update replaces most of it (the springs' multipliers by the fine
     * mesh's own gaps), so digits it converges beyond the gap between the
     * levels buy nothing.
     */
    double
    coarse_tolerance(const double relative_tolerance) const
    {
      return std::max(relative_tolerance, coarse_level_tolerance);
    }

    /** -1: automatic. */
    int    coarse_levels          = -1;
    double minimum_dofs           = 2e4;
    double coarsest_level_dofs    = 1e3;
    double coarse_level_tolerance = 1e-5;
    /** CG's first solve on the finer level starts from the coarser level's
     * displacements. */
    bool carry_displacements = true;
  };
} // namespace hrcontact

#endif
