#ifndef hrcontact_condensed_trilinos_cg_amg_h
#define hrcontact_condensed_trilinos_cg_amg_h

#include <deal.II/lac/trilinos_precondition.h>

#include <hrcontact/solvers/condensed/trilinos_back_end.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

class Epetra_MultiVector;

namespace hrcontact
{
  /**
   * CG preconditioned by Trilinos ML smoothed-aggregation AMG with the
   * rigid-body modes as near null space. The hierarchy is kept across
   * Newton steps while the matrix is, or across matrices with Reuse
   * preconditioner (applied with the values it was built from, see
   * AtSetupValues), and rebuilt when CG no longer converges with it or
   * takes more than twice its first count.
   */
  class TrilinosCgAmg : public TrilinosBackEnd
  {
  public:
    TrilinosCgAmg(const EquilibriumSystem    &system,
                  const LinearSolverSettings &settings,
                  const DofPartition         &partition,
                  const bool                  ghosted_u,
                  LinearSolverStatistics     &statistics);
    ~TrilinosCgAmg() override;

    /** CG starts from it (its constrained entries zeroed, as any warm
     * start's). */
    void
    set_start(const FieldVector &u_start) override;
    /** The tolerance x 1e-2, down to 1e-15. */
    bool
    tighten() override;

  private:
    void
    solve_assembled() override;
    void
    matrix_changing() override;
    void
    drop_matrix_dependents() override;

    /** A new AMG hierarchy for the matrix; returns its wall time. */
    double
    build_preconditioner();
    /** CG to @p tolerance (absolute); whether it converged, and its steps. */
    std::pair<bool, unsigned int>
    run_cg(const double tolerance);

    /**
     * The kept AMG hierarchy, applied with the matrix values it was built
     * from: swapped into the changing rows for the application and back
     * out for CG's own product with the current matrix.
     */
    struct AtSetupValues;

    /** CG's relative tolerance now (tighten). */
    double cg_tolerance;
    /**
     * With Reuse preconditioner: the values of the changing rows when the
     * kept AMG hierarchy was built. ML keeps a pointer to `matrix` and
     * applies its finest level with the values there, so they are swapped
     * in for each application of the preconditioner and out again for CG's
     * own products: a surface of rows, where a copy of the whole matrix was
     * kept before, with the same arithmetic.
     */
    std::vector<double>                       setup_values;
    dealii::TrilinosWrappers::PreconditionAMG preconditioner;
    std::unique_ptr<Epetra_MultiVector>       modes;
    /** Per owned node, its coordinates (x, y, z), for coordinate
     * aggregation; ML reads them during the set-up. */
    std::array<std::vector<double>, 3> node_xyz;
    bool                               built                  = false;
    unsigned int                       iterations_after_setup = 0;
  };
} // namespace hrcontact

#endif
