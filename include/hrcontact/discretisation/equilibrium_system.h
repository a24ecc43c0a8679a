#ifndef hrcontact_equilibrium_system_h
#define hrcontact_equilibrium_system_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/node_coordinates.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  class ConstraintLaw;

  /** The three row classes of eq. 38. */
  enum class RowClass
  {
    free,       ///< C: equilibrium C s = f is a hard constraint
    contact,    ///< Q: normal row of a constrained node, p = Q s - q
    prescribed, ///< H: prescribed displacement component, r = H s - f_H
  };

  /**
   * One row of the rotated equilibrium system: a combination of the dim
   * displacement rows of one node (the identity for unrotated nodes, the
   * normal or a tangent for nodes with a normal constraint). The rows of a
   * node form a basis (orthonormal unless several obstacles meet there), and
   * nodal displacements are recovered as sum_r w_r * combination_r.
   */
  struct EquilibriumRow
  {
    RowClass                                                        row_class;
    std::vector<std::pair<dealii::types::global_dof_index, double>> combination;
    /**
     * The kinematic direction d of the row, w = d . u (entries in the order
     * of `combination`). The directions of a node form its primal basis and
     * the combinations the dual one (c_r . d_s = delta_rs): p_r = c_r . (B s
     * - f) and the nodal reaction is sum_r p_r d_r, the conic combination of
     * eq. 11 when several obstacles meet at a node. Empty: d = c (an
     * orthonormal basis, every node but those).
     */
    std::vector<double> direction;
    double
    direction_component(const unsigned int k) const
    {
      return direction.empty() ? combination[k].second : direction[k];
    }
    /** Prescribed value: u-hat for H rows, the gap g for Q rows. */
    double       value = 0;
    unsigned int node  = 0;
    /** Q rows only: unilateral contact (w_n - g <= 0, p <= 0) rather than a
     * bilateral constraint w_n = g. */
    bool unilateral = false;
    /** Q rows of obstacles: the boundary id whose obstacle it is, else -1. */
    int obstacle = -1;
    /**
     * Q rows only: a constraint law of its own (a two-sided stop, ...);
     * null: unilateral contact or a bilateral constraint as `unilateral`
     * says, regularised as the solver is set up.
     */
    std::shared_ptr<const ConstraintLaw> law;
    /**
     * The hanging dofs whose equilibrium equations this row carries (a
     * locally refined mesh), with their weights sum_j c_j a_hj: the
     * conforming test function of the row is that of its node plus a_hj
     * times each hanging node's that depends on it. The load f~_r
     * (row_load) includes them, the internal force B~_r s through
     * HangingShareForces (the cells around a hanging node may be on other
     * processes: row_times has the combination only); the direction
     * (kinematic) does not, as a hanging node's displacement follows its
     * parents'. Empty on a uniform mesh.
     */
    std::vector<std::pair<dealii::types::global_dof_index, double>> shares;
  };

  /** The blocks of one cell as the assembler computes them (section 4.2). */
  struct CellBlocks
  {
    /** Active cell index. */
    unsigned int                                 cell = 0;
    std::vector<dealii::types::global_dof_index> displacement_dofs;
    std::vector<dealii::types::global_dof_index> stress_dofs;
    /** B_c: displacement dofs x stress dofs. */
    dealii::FullMatrix<double> B;
    /** F_c: stress dofs x stress dofs. */
    dealii::FullMatrix<double> F;
    /** The cell's share of the load vector f (empty when the blocks come
     * from storage). */
    dealii::Vector<double> load;
    /**
     * The linear term d_c = e_c - F_c s_c of a material Newton step at the
     * stress state s (HRAssembler::stress_state), e_c = int psi : eps(s)
     * the strain of the law: the complementary energy's second-order
     * expansion about s is 1/2 s^T F_c s + d_c^T s + const. Empty for a
     * linear law and before a state is given (d_c = 0).
     */
    dealii::Vector<double> strain_term;
    /**
     * Whether B and F are those of the cell handed to the worker just
     * before (this cell is a translation of it and the material is
     * homogeneous), to the last bit: a worker may keep what it derived from
     * them, such as F_c^{-1} B_c^T and K_c.
     */
    bool same_as_previous = false;
  };

  /**
   * The discrete blocks of section 4.2 with the row classification: the
   * block-diagonal flexibility F (one dense SPD block per cell), the
   * equilibrium matrix B (displacement rows x stress columns, B_ij =
   * int eps(phi_i) : psi_j), the load vector f, and the rotated rows.
   * Dimension-independent: the reduction and the solvers only see this.
   */
  struct EquilibriumSystem
  {
    unsigned int dim                 = 2;
    unsigned int n_displacement_dofs = 0;
    unsigned int n_stress_dofs       = 0;

    std::vector<std::vector<dealii::types::global_dof_index>> cell_stress_dofs;
    std::vector<std::vector<dealii::types::global_dof_index>>
                                            cell_displacement_dofs;
    std::vector<dealii::FullMatrix<double>> cell_flexibility;
    /**
     * Per cell the strain term d_c of CellBlocks at the last stress state
     * (HRAssembler::refresh_flexibility); empty when the law is linear, and
     * a cell's entry empty where d_c = 0.
     */
    std::vector<dealii::Vector<double>> cell_strain_term;

    dealii::SparsityPattern sparsity;
    /** Rows by b_row(displacement dof), columns by global stress dof. */
    dealii::SparseMatrix<double> B;
    /**
     * The displacement dofs B has rows for, in the order of its rows: empty
     * for every dof (row i is dof i); on a distributed mesh the owned and
     * ghost dofs, the only ones its stored cells reach, so that B's row
     * starts cost 8 bytes a dof of this process instead of the whole mesh.
     */
    dealii::IndexSet B_dofs;
    /** B's row of a displacement dof (one B_dofs holds). */
    unsigned int
    b_row(const dealii::types::global_dof_index dof) const
    {
      if (B_dofs.size() == 0)
        return dof;
      AssertThrow(B_dofs.is_element(dof),
                  dealii::ExcMessage(
                    "B has no row for displacement dof " + std::to_string(dof) +
                    " on this process (a distributed mesh keeps the rows of "
                    "its owned and ghost dofs)"));
      return B_dofs.index_within_set(dof);
    }
    /**
     * The load vector f: complete on a serial mesh (also under MPI); on a
     * distributed mesh the owned and ghost (relevant) dofs only, which are
     * all that the owned cells, the rows of owned nodes and the reactions
     * read (8 bytes a dof of the whole mesh on every process before: 13 MB
     * at Hertz refinement 9).
     */
    FieldVector load;

    /**
     * Lean storage, for the condensed path on large meshes: B, F and the cell
     * dofs are kept only for the cells marked here, those that touch the node
     * of a Q or H row, which is all that p = Q s - q and the support
     * reactions need. Every other cell's blocks are recomputed on demand by
     * `recompute_cell_blocks`, once when the condensed stiffness is built and
     * once for the final stresses, so the memory of the replicated blocks
     * (about 3 KB per cell in 2D, 30 KB in 3D) is not spent. Empty: every
     * cell is stored (the null-space path needs them all).
     */
    std::vector<bool> stored_cell;
    /** Calls the worker with the blocks of every cell the filter accepts. */
    std::function<void(const std::function<bool(unsigned int)> &,
                       const std::function<void(const CellBlocks &)> &)>
      recompute_cell_blocks;

    /** Calls the worker with the displacement dofs of every cell the filter
     * accepts (a lean system's cells that are not stored), without
     * computing its blocks. */
    std::function<
      void(const std::function<bool(unsigned int)> &,
           const std::function<
             void(unsigned int,
                  const std::vector<dealii::types::global_dof_index> &)> &)>
      recompute_cell_dofs;

    /** Number of active cells. */
    unsigned int
    n_cells() const
    {
      return cell_stress_dofs.size();
    }
    bool
    is_stored(const unsigned int cell) const
    {
      return stored_cell.empty() || stored_cell[cell];
    }
    /**
     * The blocks of every cell the filter accepts, from storage where the
     * cell is stored and recomputed otherwise; in cell order.
     */
    void
    for_each_cell_blocks(
      const std::function<bool(unsigned int)>       &filter,
      const std::function<void(const CellBlocks &)> &worker) const;

    /**
     * The displacement dofs of every cell the filter accepts, from storage or
     * from the mesh, in cell order: the sparsity pattern of the condensed
     * stiffness, without buffering a K_c per cell.
     */
    void
    for_each_cell_dofs(
      const std::function<bool(unsigned int)>                  &filter,
      const std::function<void(
        unsigned int,
        const std::vector<dealii::types::global_dof_index> &)> &worker) const;

    std::vector<EquilibriumRow> rows;
    std::vector<unsigned int>   free_rows, contact_rows, prescribed_rows;
    /**
     * The hanging-node constraints of a locally refined mesh (u_h = sum_j
     * a_hj u_j, on this process's relevant dofs), closed; empty on a
     * uniform mesh. A hanging dof has no row of its own: its equation is
     * shared among its parents' rows (EquilibriumRow::shares), and every
     * displacement solve imposes these constraints.
     */
    dealii::AffineConstraints<double> hanging_nodes;
    /** The number of hanging dofs of the whole mesh. */
    unsigned int n_hanging_dofs = 0;
    /** Complete on a serial mesh; on a distributed one this process's
     * nodes and the constrained boundary's (NodeCoordinates). */
    NodeCoordinates node_coordinates;
    /**
     * A scene of several bodies (Bodies): the body (cell material id) of
     * each node of the constrained boundary, so that every body's rigid
     * motions can be checked on its own; empty for one body.
     */
    std::map<unsigned int, unsigned int> node_body;
    unsigned int                         n_bodies = 1;

    /**
     * Lean rows, for the condensed path on large meshes: `rows` holds only
     * the rows of nodes with a Q or H row (or a rotated basis); the free row
     * of any other dof is implicit, the unit row of its component at its
     * node (dof_node, dof_component), and `free_rows` lists only the stored
     * free rows. One EquilibriumRow costs about 150 bytes with its heap
     * allocations, 1.3 GB per process at 6.3M dofs; the implicit rows cost
     * 5 bytes a dof. The null-space path needs every row (false).
     */
    bool lean_rows = false;
    /** Every free row, stored or implicit (eq. 38's n). */
    unsigned int n_free_rows = 0;
    /**
     * The node and the component of a displacement dof. The dofs of a node
     * are consecutive (Q1^dim, numbered vertex by vertex, never renumbered;
     * HRAssembler::classify_rows checks it), so node n has the dofs dim n
     * ... dim n + dim - 1, in the serial and the distributed numbering
     * alike, and no map is stored.
     */
    unsigned int
    dof_node(const dealii::types::global_dof_index i) const
    {
      return i / dim;
    }
    unsigned int
    dof_component(const dealii::types::global_dof_index i) const
    {
      return i % dim;
    }

    /**
     * B s - f over every cell, from storage or recomputed: the equilibrium
     * residual of any row, for checks on a serial mesh (f complete). A lean
     * system evaluates every cell again. On a locally refined mesh the
     * conforming residual T^T (B s - f): each hanging dof's entry added to
     * its parents' (EquilibriumRow::shares) and zero itself.
     */
    void
    equilibrium_residual(const dealii::Vector<double> &s,
                         dealii::Vector<double>       &residual) const;

    /** (B~ s)_r for the rotated row r; in a lean system only for Q and H
     * rows (the stored cells are theirs). Any vector indexed by stress dof:
     * a dealii::Vector, or a FieldVector holding the cells around the row's
     * node. */
    template <typename VectorType>
    double
    row_times(const EquilibriumRow &row, const VectorType &s) const
    {
      double sum = 0;
      for (const auto &[dof, c] : row.combination)
        for (auto it = B.begin(b_row(dof)); it != B.end(b_row(dof)); ++it)
          sum += c * it->value() * s(it->column());
      return sum;
    }

    /** v += coefficient * (B~_r)^T. */
    void
    add_row_transpose(const EquilibriumRow   &row,
                      const double            coefficient,
                      dealii::Vector<double> &v) const;

    /** The rotated load f~_r (the row's node must be owned or ghost on a
     * distributed mesh). */
    double
    row_load(const EquilibriumRow &row) const;

    /** Whether some Q row is unilateral or follows a constraint law: the
     * scene has contact, solved by the augmented Lagrangian. */
    bool
    has_contact() const;

    /** Each Q row's value g: the w_n of every row held at its gap. */
    std::vector<double>
    contact_row_values() const;

    /** Fs = F s, cell block by cell block. */
    void
    multiply_flexibility(const dealii::Vector<double> &s,
                         dealii::Vector<double>       &Fs) const;

    /**
     * v += d, the strain terms of a material Newton step (cell_strain_term;
     * nothing for a linear law): with them F s + d is the gradient of the
     * expanded complementary energy, the strain the stresses s would have
     * under the law linearised at the last state.
     */
    void
    add_strain_terms(dealii::Vector<double> &v) const;

    /** Global displacement vector from one value per row (every row
     * stored: not for lean rows). */
    void
    displacements_from_row_values(const std::vector<double> &row_values,
                                  dealii::Vector<double>    &u) const;

    /** "node (x, y)" and, for rotated rows, the direction. */
    std::string
    describe_row(const unsigned int r) const;
    std::string
    describe_node(const unsigned int node) const;
  };
  /**
   * The number of rigid-body motions (translations and rotations) that the
   * prescribed rows and the bilateral Q rows leave free: the motions along
   * which only unilateral contacts hold the body. A motion m is held when
   * some such row has d . m(x) != 0 at its node; the count is the dimension
   * of the null space of those rows restricted to the rigid motions.
   */
  unsigned int
  rigid_motions_held_only_by_contact(const EquilibriumSystem &system);

  /** The same for each body of a multi-body scene (by body index), each
   * held only by the rows at its own nodes. */
  std::vector<unsigned int>
  rigid_motions_held_only_by_contact_by_body(const EquilibriumSystem &system);

  /**
   * The rigid-body motions that no row holds whatever the contact state
   * (the prescribed rows and every contact row, taken as bilateral), named
   * ("translation along x"), for each body. A frictionless foundation
   * holds only its normal: a body on it with no support along it floats,
   * and no contact iteration can change that. No entry at all where a
   * contact row couples several nodes (a contact pair, which may hold a
   * body through another one).
   */
  std::vector<std::vector<std::string>>
  rigid_motions_no_row_holds(const EquilibriumSystem &system);

} // namespace hrcontact

#endif
