#ifndef hrcontact_newton_step_path_h
#define hrcontact_newton_step_path_h

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/solvers/linear_solver_settings.h>

#include <vector>

namespace hrcontact
{
  /**
   * One exact Newton step of the augmented Lagrangian (doc/method.md, "Two
   * exact Newton-step paths"): the maximiser of the quadratic piece of eq. 44
   * that the constraint laws select, one ContactPiece per Q row: a held row
   * keeps w_n = g + offset, a spring row w_n - g = offset - compliance p. The
   * two implementations (NullSpaceStep, CondensedStep) give the same iterates
   * in exact arithmetic.
   */
  class NewtonStepPath
  {
  public:
    virtual ~NewtonStepPath() = default;

    /**
     * Solve the piece; return p = Q s - q for the Q rows this process sees
     * (row_partition().relevant(): every row on one process). Only the
     * pieces of those rows are read.
     */
    virtual void
    solve(const std::vector<ContactPiece> &pieces, std::vector<double> &p) = 0;

    /** Which Q rows this process owns and sees (every row unless the path
     * is distributed). */
    const ContactRowPartition &
    row_partition() const
    {
      return row_ownership;
    }

    /**
     * The unilateral shorthand: released rows are springs of compliance
     * alpha_i anchored at g_i + mu_i, the others are held at w_n = g.
     */
    void
    solve(const std::vector<bool>   &released,
          const std::vector<double> &mu,
          const std::vector<double> &alpha,
          std::vector<double>       &p);

    /**
     * Stresses of the last solve into s, sized by reinit_field(): on a
     * distributed mesh each process fills its own cells' and its ghost
     * cells' entries, without a global vector; otherwise s is complete.
     */
    virtual void
    stresses(FieldVector &s) const = 0;

    /**
     * Displacements to start the next solve's iterations from (nested
     * iteration: the coarser level's, prolongated), indexed as the
     * displacement dofs; distributed or complete as reinit_field makes it.
     * Exact solvers have no use for it and ignore it.
     */
    virtual void
    set_start(const FieldVector &u_start);

    /**
     * Nodal displacements of the last solve, given the normal displacements
     * of the Q rows (g + mu after the last multiplier update), into u sized
     * by the caller: distributed (reinit_field) or complete (reinit(n), then
     * gathered on every process).
     */
    virtual void
    displacements(const std::vector<double> &contact_w,
                  FieldVector               &u) const = 0;

    /** Whether displacements() reads nothing from contact_w (the path
     * solves for u itself), so that a caller without the contact state
     * may ask for u. */
    virtual bool
    displacements_are_unknowns() const
    {
      return false;
    }

    /**
     * w_n = d . u of the Q rows this process sees after the last solve,
     * needed by the displacement AL for rows without a spring. The null-space
     * path knows u only through the rows' w_n, so it cannot (and throws
     * InputError).
     */
    virtual void
    contact_displacements(std::vector<double> &w) const;

    /**
     * A RowRelinearisation rewrote the directions and gaps of some Q rows
     * between multiplier updates: the next solve must use them. The
     * condensed path reads the rows at every solve and only drops a kept
     * factorisation; the null-space path built its reduction from the initial
     * rows and cannot follow (InputError).
     */
    virtual void
    rows_changed();

    /**
     * The cells' F_c in the system changed (a material whose compliance
     * depends on its state, MaterialLaw; see HRAssembler::refresh_flexibility):
     * rebuild what depends on F before the next solve.
     */
    virtual void
    flexibility_changed() = 0;

    /**
     * The inner Newton iteration came back to a released set it had solved
     * (AugmentedLagrangianSolver): with an iterative linear solver, the
     * usual cause is that its residual no longer fixes p = Q s - q to the
     * digits the constraint laws compare (measured on Hertz refinement 10,
     * 6.3M dofs, at Tolerance 1e-12). Tighten it for the remaining solves;
     * false when the path solves exactly (dense, direct) or CG is at its
     * floor already.
     */
    virtual bool
    tighten_linear_solver();

    /** Linear solver counters (zero for the dense path). */
    LinearSolverStatistics statistics;

  protected:
    /** Set by the constructor of a distributed path. */
    ContactRowPartition row_ownership;
  };
} // namespace hrcontact

#endif
