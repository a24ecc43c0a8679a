#ifndef hrcontact_condensed_step_rows_h
#define hrcontact_condensed_step_rows_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>

#include <vector>

namespace hrcontact
{
  /** A released Q row: a spring of stiffness 1/compliance along the row's
   * direction d, anchored at g + offset. */
  struct Spring
  {
    const EquilibriumRow *row;
    const ContactPiece   *piece;

    /** The node matrix k d d^T and the force k (g + offset) d. */
    void
    matrix_and_force(dealii::FullMatrix<double> &matrix,
                     dealii::Vector<double>     &force) const;
  };

  /**
   * What one Newton step of the condensed path imposes on K u = f: the held
   * rows (prescribed rows, and Q rows whose piece holds them) as
   * AffineConstraints on this process's relevant dofs, the springs of the
   * released Q rows it owns, and the key of the matrix they give.
   */
  struct StepRows
  {
    /**
     * Built on every process (collective: an error found at one process's
     * nodes, linearly dependent rows at a corner, stops every process, or
     * the others would wait in the assembly's communication).
     */
    StepRows(const EquilibriumSystem         &system,
             const DofPartition              &partition,
             const ContactRowPartition       &row_ownership,
             const std::vector<ContactPiece> &pieces);

    dealii::AffineConstraints<double> constraints;
    std::vector<Spring>               springs;
    /**
     * What K and the springs depend on, beyond the fixed part: per Q row
     * held (-1) or the spring's compliance, and its direction (rows that
     * follow the configuration move it, and a matrix of the old directions
     * would be off by as much). The held values and the spring anchors
     * (g + offset) enter the right-hand side only. Each process keys the
     * rows it sees; a back end agrees on keeping its matrix with the others.
     */
    std::vector<double> key;
  };
} // namespace hrcontact

#endif
