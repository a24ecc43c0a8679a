#ifndef hrcontact_condensed_held_rows_h
#define hrcontact_condensed_held_rows_h

#include <deal.II/lac/affine_constraints.h>

#include <hrcontact/discretisation/equilibrium_system.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  /** A row held at a value: d . u = value (a prescribed row, or a Q row
   * held at g + offset). */
  using HeldRow = std::pair<const EquilibriumRow *, double>;

  /**
   * d . u = value for one held row: the dof with the largest |d_k| is
   * expressed by the others of the row.
   */
  void
  constrain_row(const EquilibriumRow              &row,
                const double                       value,
                dealii::AffineConstraints<double> &constraints);

  /**
   * Several rows held at one node (a node in a corner between obstacles,
   * eq. 11): d_r . u = value_r jointly, by Gauss-Jordan elimination with the
   * largest pivot of each row, so that every constrained dof is expressed
   * by the free ones only. The rows share their dofs (those of the node).
   * Linearly dependent rows (obstacles with parallel normals) are an
   * InputError naming the node by @p describe_node.
   */
  void
  constrain_jointly(
    const std::vector<HeldRow>                           &rows,
    dealii::AffineConstraints<double>                    &constraints,
    const std::function<std::string(const unsigned int)> &describe_node);
} // namespace hrcontact

#endif
