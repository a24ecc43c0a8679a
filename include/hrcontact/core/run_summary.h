#ifndef hrcontact_run_summary_h
#define hrcontact_run_summary_h

#include <hrcontact/core/results.h>
#include <hrcontact/postprocess/summary.h>

namespace hrcontact
{
  /**
   * The run's own keys of summary.txt (doc/design.md, "Outputs"): the
   * dimensions, the path and its linear solver, the contact, material and
   * stress-constraint iterations and the nested levels. The postprocessors
   * add theirs after it.
   */
  template <int dim>
  class RunSummary
  {
  public:
    /** Start `summary` afresh with the keys of `results`;
     * `elastic_solve_timed`: Output/Time a linear elastic solve. */
    static void
    fill(const Results<dim> &results,
         const bool          elastic_solve_timed,
         Summary            &summary);

  private:
    /** Each adaptive cycle's cells, dofs, estimate and time. */
    static void
    add_adaptive_cycles(const Results<dim> &r, Summary &summary);
    static void
    add_linear_solver(const Results<dim> &results,
                      const bool          elastic_solve_timed,
                      Summary            &summary);
    static void
    add_material(const Results<dim> &results, Summary &summary);
    static void
    add_coarse_levels(const Results<dim> &results, Summary &summary);
  };
} // namespace hrcontact

#endif
