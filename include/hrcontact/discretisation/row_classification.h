#ifndef hrcontact_row_classification_h
#define hrcontact_row_classification_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <hrcontact/constraints/constraint_source.h>
#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <vector>

namespace hrcontact
{
  /**
   * The rows of the equilibrium system (eq. 38) node by node: free rows C,
   * contact rows Q and prescribed rows H. Each constraint kind of the scene
   * (ConstraintSource) collects what it asks of the nodes of its boundary
   * faces; then one pass builds each node's rows: prescribed components,
   * a corner between obstacles (eq. 11: the normals and free directions as
   * the primal basis, the force rows its dual basis), a kind's own row (a
   * stop), a normal constraint or obstacle, and free rows spanning what is
   * left. On a distributed mesh every process classifies the whole
   * constrained boundary (a surface), gathered from the owners of its
   * faces, so that the rows are the same everywhere.
   */
  template <int dim>
  class RowClassification
  {
  public:
    RowClassification(const Scene<dim> &scene, const MixedSpaces<dim> &spaces);

    /**
     * The rows, the node coordinates (the owned nodes and those of the
     * constrained boundary on a distributed mesh) and the sizes of
     * @p system. With @p lean_rows only the nodes some constraint touches
     * get explicit rows (the condensed path); the others' unit rows are
     * implicit.
     */
    void
    classify(EquilibriumSystem &system, const bool lean_rows) const;

  private:
    /** The coordinates of the nodes this process keeps. */
    void
    read_node_coordinates(EquilibriumSystem &system) const;
    /** The boundary faces of this process's cells some constraint kind
     * acts on. */
    std::vector<BoundaryFace<dim>>
    constrained_faces() const;
    /** The rows of one node from what the constraint kinds asked of it. */
    void
    classify_node(const unsigned int          node,
                  const NodeConstraints<dim> &c,
                  EquilibriumSystem          &system,
                  const bool                  lean_rows) const;
    /** A corner between obstacles (eq. 11). */
    void
    corner_rows(const unsigned int          node,
                const NodeConstraints<dim> &c,
                EquilibriumSystem          &system) const;
    /** A normal constraint or an obstacle at the node, adding its
     * direction to @p taken. */
    void
    normal_row(const unsigned int                   node,
               const NodeConstraints<dim>          &c,
               EquilibriumSystem                   &system,
               std::vector<dealii::Tensor<1, dim>> &taken) const;

    const Scene<dim>       &scene;
    const MixedSpaces<dim> &spaces;
  };

  /**
   * Every process's @p faces, in process order, on every process (the
   * boundary faces of a distributed mesh, packed into one all-gather).
   */
  template <int dim>
  std::vector<BoundaryFace<dim>>
  gather_boundary_faces(const std::vector<BoundaryFace<dim>> &faces,
                        const MPI_Comm                        communicator);

  /**
   * The free directions of a node: Gram-Schmidt remainders of the unit axes
   * (in axis order) against the orthonormal directions `taken`, until they
   * span the space.
   */
  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  orthogonal_complement(const std::vector<dealii::Tensor<1, dim>> &taken);
} // namespace hrcontact

#endif
