#ifndef hrcontact_condensed_linear_back_end_h
#define hrcontact_condensed_linear_back_end_h

#include <deal.II/base/types.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/solvers/condensed/step_rows.h>
#include <hrcontact/solvers/condensed/strain_loads.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  /** Takes one owned cell's K_c with its displacement dofs. */
  using CellStiffnessSink =
    std::function<void(const unsigned int,
                       const std::vector<dealii::types::global_dof_index> &,
                       const dealii::FullMatrix<double> &)>;

  /**
   * The linear algebra of the condensed path (CondensedStep): K = B F^-1 B^T
   * assembled once from the owned cells, then per Newton step K u = f with
   * the step's held rows as constraints and its springs added. One
   * implementation per back end, chosen by create_condensed_back_end():
   * UMFPACK (serial, direct), Trilinos CG + ML AMG, and MUMPS (MumpsFactor)
   * (direct on several processes). Adding one is a new file pair and a line
   * in the factory.
   */
  class CondensedBackEnd
  {
  public:
    virtual ~CondensedBackEnd() = default;

    /**
     * Build K: @p couplings adds the pattern of the owned cells and of the
     * rows that couple nodes, @p cells streams each owned cell's K_c once.
     */
    virtual void
    assemble(
      const std::function<void(dealii::DynamicSparsityPattern &)> &couplings,
      const std::function<void(const CellStiffnessSink &)>        &cells) = 0;

    /**
     * Solve K u = load + strain loads with the held rows and springs of
     * @p rows, into u: complete, or the relevant dofs of a distributed mesh
     * (as the back end was created).
     */
    virtual void
    solve(const StepRows &rows, const StrainLoads &loads, FieldVector &u) = 0;

    /** An iterative back end starts from u_start; the others ignore it. */
    virtual void
    set_start(const FieldVector &u_start);

    /** The rows' directions moved: a kept factorisation no longer fits. */
    virtual void
    rows_changed() = 0;

    /** K is about to be assembled again (F changed): drop what was built
     * on the old one. */
    virtual void
    flexibility_changed() = 0;

    /** An iterative back end's tolerance x 1e-2 (NewtonStepPath::
     * tighten_linear_solver); false for a direct one. */
    virtual bool
    tighten();
  };

  /**
   * The back end for @p solver: CG + AMG, else MUMPS when the partition is
   * distributed, else UMFPACK. With @p ghosted_u the solution holds the
   * owned and ghost dofs of a distributed mesh only.
   */
  std::unique_ptr<CondensedBackEnd>
  create_condensed_back_end(const LinearSolverKind      solver,
                            const EquilibriumSystem    &system,
                            const LinearSolverSettings &settings,
                            const DofPartition         &partition,
                            const bool                  ghosted_u,
                            LinearSolverStatistics     &statistics);

  /** What a singular K means to the user (a direct back end's failure). */
  extern const std::string singular_stiffness_message;

  /** A direct back end found K singular (singular_stiffness_message): an
   * input error, which the material loop can name more closely (a cracked
   * region held only by the residual stiffness). */
  class SingularStiffnessError : public InputError
  {
  public:
    using InputError::InputError;
  };
} // namespace hrcontact

#endif
