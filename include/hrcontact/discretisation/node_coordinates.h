#ifndef hrcontact_node_coordinates_h
#define hrcontact_node_coordinates_h

#include <deal.II/base/mpi.h>

#include <array>
#include <utility>
#include <vector>

namespace hrcontact
{
  /**
   * The coordinates of the mesh's nodes (vertices; node n has the
   * displacement dofs dim n + d, EquilibriumSystem::dof_node), indexed by
   * global node number either way. Complete on a serial mesh. On a
   * parallel::distributed::Triangulation a process keeps only the nodes it
   * owns (a contiguous range in p4est's numbering: the AMG's rigid-body
   * modes read them) and the nodes of the rows' boundary faces (classified
   * on every process: the rows, their error messages and the result tables
   * read them), instead of 24 bytes a node of the whole mesh on every
   * process (19 MB at Hertz refinement 9). Asking for a node the process
   * does not keep is an error, never a silent zero.
   */
  class NodeCoordinates
  {
  public:
    using Point = std::array<double, 3>;

    /** Every node of a mesh of n_nodes, at the origin. */
    void
    reinit(const unsigned int n_nodes);
    /** A process's share of a distributed mesh of n_nodes: its own range
     * [first_owned, first_owned + n_owned); other nodes by set(). */
    void
    reinit(const unsigned int n_nodes,
           const unsigned int first_owned,
           const unsigned int n_owned);

    /** Owned or complete: written in place; otherwise kept as one of the
     * other nodes (a later set() of the same node is ignored). */
    void
    set(const unsigned int node, const Point &x);

    /**
     * Done setting: sorts the other nodes and computes the centre (the mean
     * of every node) and the extent (the largest coordinate distance from
     * it) over the whole mesh, summing the owned ranges of the processes of
     * the communicator on a distributed store.
     */
    void
    compress(const MPI_Comm communicator = MPI_COMM_SELF);

    /** The node's coordinates; throws ExcMessage for a node this process
     * does not keep. */
    const Point &
    operator[](const unsigned int node) const;

    /** Whether this process keeps the node. */
    bool
    knows(const unsigned int node) const;

    /** The number of nodes of the whole mesh. */
    unsigned int
    size() const
    {
      return n_nodes;
    }
    /** Whether every node is kept (a serial mesh). */
    bool
    is_complete() const
    {
      return first_owned == 0 && owned.size() == n_nodes;
    }
    /** The mean of every node of the mesh (after compress()). */
    const Point &
    centre() const
    {
      return mean;
    }
    /** max over nodes and axes of |x_d - centre_d| (after compress()). */
    double
    extent() const
    {
      return largest_distance;
    }

  private:
    unsigned int                                n_nodes     = 0;
    unsigned int                                first_owned = 0;
    std::vector<Point>                          owned;
    std::vector<std::pair<unsigned int, Point>> others;
    Point                                       mean             = {};
    double                                      largest_distance = 0;
  };
} // namespace hrcontact

#endif
