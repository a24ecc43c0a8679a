#ifndef hrcontact_hanging_nodes_h
#define hrcontact_hanging_nodes_h

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <hrcontact/discretisation/equilibrium_system.h>

namespace hrcontact
{
  /**
   * The hanging nodes of a locally refined mesh, on the condensed path: the
   * conforming Q1 space constrains each hanging dof to its parents (u_h =
   * sum_j a_hj u_j), so its test function is not one of the space's. Its
   * equilibrium equation has no row of its own; the row of each parent dof
   * carries a_hj times it (eq. 38 on the conforming test space, T^T (B s -
   * f) = 0 with T the constraints' matrix). This fills
   * EquilibriumSystem::hanging_nodes (on @p relevant, the dofs of this
   * process's owned and ghost cells) and n_hanging_dofs; nothing on a
   * uniform mesh.
   */
  template <int dim>
  void
  find_hanging_nodes(const dealii::DoFHandler<dim> &dof_handler,
                     const dealii::IndexSet        &relevant,
                     EquilibriumSystem             &system);

  /** Whether a displacement dof hangs (has no row of its own). */
  inline bool
  is_hanging(const EquilibriumSystem              &system,
             const dealii::types::global_dof_index dof)
  {
    return system.n_hanging_dofs > 0 &&
           system.hanging_nodes.is_constrained(dof);
  }

  /**
   * Each explicit row's EquilibriumRow::shares from the hanging nodes whose
   * parents its combination names: weight sum_j c_j a_hj per hanging dof h.
   */
  void
  add_hanging_shares(EquilibriumSystem &system);
} // namespace hrcontact

#endif
