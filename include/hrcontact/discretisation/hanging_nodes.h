#ifndef hrcontact_hanging_nodes_h
#define hrcontact_hanging_nodes_h

#include <deal.II/base/index_set.h>

#include <deal.II/dofs/dof_handler.h>

#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>

#include <functional>
#include <map>
#include <vector>

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

  /** Whether a displacement dof hangs (has no row of its own); false for a
   * dof this process does not see. */
  inline bool
  is_hanging(const EquilibriumSystem              &system,
             const dealii::types::global_dof_index dof)
  {
    if (system.n_hanging_dofs == 0)
      return false;
    const dealii::IndexSet &lines = system.hanging_nodes.get_local_lines();
    return (lines.size() == 0 || lines.is_element(dof)) &&
           system.hanging_nodes.is_constrained(dof);
  }

  /**
   * The hanging dofs that depend on each parent dof (with a_hj), from the
   * system's hanging-node constraints: the shares of any combination.
   */
  class HangingChildren
  {
  public:
    explicit HangingChildren(const EquilibriumSystem &system);

    /** sum_j c_j a_hj per hanging dof h, for the combination c. */
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    shares_of(
      const std::vector<std::pair<dealii::types::global_dof_index, double>>
        &combination) const;

  private:
    std::map<dealii::types::global_dof_index,
             std::vector<std::pair<dealii::types::global_dof_index, double>>>
      children;
  };

  /**
   * Each explicit row's EquilibriumRow::shares from the hanging nodes whose
   * parents its combination names: weight sum_j c_j a_hj per hanging dof h.
   */
  void
  add_hanging_shares(EquilibriumSystem &system);

  /**
   * The internal forces (B s)_h of the hanging dofs some row shares, each
   * summed over every process's owned cells: the cells around a hanging node
   * need not be ghosts of the process that owns its parent's row, so each
   * process adds its own cells' part and the sums meet at the owners (and
   * their ghosts). The row's part is then sum_h w_h (B s)_h
   * (EquilibriumRow::shares); EquilibriumSystem::row_times has the rest.
   * Collective; nothing to do on a uniform mesh.
   */
  class HangingShareForces
  {
  public:
    /** The terms of this process's owned stored cells. */
    HangingShareForces(const EquilibriumSystem &system,
                       const DofPartition      &partition);

    /** One term: the B entry of a hanging dof against a stress column. */
    struct Term
    {
      dealii::types::global_dof_index hanging;
      dealii::types::global_dof_index column;
      double                          b;
    };
    const std::vector<Term> &
    terms() const
    {
      return terms_;
    }

    /** The sums with @p stress(k) the stress of term k's column. */
    void
    evaluate(const std::function<double(std::size_t)> &stress);

    /** sum_h w_h (B s)_h of the row's shares (zero without). */
    double
    of_row(const EquilibriumRow &row) const;

  private:
    bool              any = false;
    std::vector<Term> terms_;
    FieldVector       forces;
  };
} // namespace hrcontact

#endif
