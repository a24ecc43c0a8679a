#ifndef hrcontact_reactions_h
#define hrcontact_reactions_h

#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>

#include <array>
#include <vector>

namespace hrcontact
{
  /**
   * The reactions B~_r s - f~_r of `rows` (indices into system.rows), each
   * computed by the owner of its node (on a distributed mesh only it has
   * every cell around the node) and summed over the processes.
   *
   * On several processes a master node's row may hold alpha n at a slave
   * node of a contact pair (ContactPairs::couple_rows), whose cells its
   * owner does not have; that part is alpha times the pair row's reaction,
   * read from `pair_reactions` (one per Q row: the Q rows' reactions, which
   * are therefore computed first; the slave's other rows are free, with no
   * residual). `pair_reactions` may be `values` itself.
   */
  void
  row_reactions(const EquilibriumSystem         &system,
                const DofPartition              &partition,
                const FieldVector               &stress_unknowns,
                const std::vector<unsigned int> &rows,
                const std::vector<double>       &pair_reactions,
                std::vector<double>             &values);

  /** The displacement of the node of each Q row (its first dim dofs),
   * read by the owner of the node and complete on every process. */
  std::vector<std::array<double, 3>>
  contact_node_displacements(const EquilibriumSystem &system,
                             const DofPartition      &partition,
                             const FieldVector       &displacement);
} // namespace hrcontact

#endif
