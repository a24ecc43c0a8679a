#ifndef hrcontact_dof_partition_h
#define hrcontact_dof_partition_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace hrcontact
{
  struct EquilibriumSystem;

  /**
   * Which displacement dofs and cells one MPI process owns in the condensed
   * path's distributed linear algebra: read from the DoFHandler of a
   * distributed mesh, or mapped from p4est onto a replicated serial mesh.
   * The stiffness K, its constraints, the AMG hierarchy, the CG vectors and
   * the cell work are distributed by it, and the contact rows' iteration
   * by the owners of their nodes (ContactRowPartition).
   */
  struct DofPartition
  {
    MPI_Comm     communicator = MPI_COMM_SELF;
    unsigned int n_processes  = 1;
    unsigned int process      = 0;
    /** Dofs whose matrix rows this process assembles and solves for. */
    dealii::IndexSet owned;
    /** owned plus the dofs of the ghost cells (constraints live here). */
    dealii::IndexSet relevant;
    /** Per active cell index: whether this process assembles the cell. */
    std::vector<bool> owned_cell;
    /**
     * Read from a parallel::distributed::Triangulation: owned is a
     * contiguous range (p4est numbering), and the cells this process does
     * not own or see as ghosts are artificial. False on a serial mesh, also
     * when p4est's partition was mapped onto it.
     */
    bool distributed_mesh = false;

    bool
    distributed() const
    {
      return n_processes > 1;
    }
    /**
     * Rows over the nodes of two bodies (contact pairs): the process that
     * owns a row's node also reads and writes the row's other dofs (w = d .
     * u, the held row's constraint, the master rows' fill-in), so they join
     * its relevant dofs. A surface's worth, like the rows. Nothing serially.
     */
    void
    add_dofs_of_rows_across_nodes(const EquilibriumSystem &system);

    /** "2 processes, 1234 to 1250 dofs each", for the log. */
    std::string
    describe() const;
  };

  /**
   * Whether this is process 0 of the communicator, the one that prints and
   * writes; true in programs that never initialise MPI.
   */
  bool
  is_root_process(const MPI_Comm communicator);

  /** Everything owned by the one process of MPI_COMM_SELF. */
  DofPartition
  serial_partition(const unsigned int n_dofs, const unsigned int n_cells);

  /**
   * The partition of deal.II's p4est forest. On a
   * parallel::distributed::Triangulation it is the mesh's own (owned and
   * locally relevant dofs, owned cells by this process's active cell
   * index). On a serial mesh under MPI (kept where every process needs
   * every cell), a p4est forest is built from its coarse mesh and refined to
   * the same level, and its cells (matched by their child paths) and dof
   * ownership are carried over to the serial numbering; the serial mesh
   * must be uniformly refined (every scene is). With one process this is
   * serial_partition().
   */
  template <int dim>
  DofPartition
  partition_with_p4est(const dealii::Triangulation<dim> &triangulation,
                       const dealii::DoFHandler<dim>    &dof_handler,
                       const MPI_Comm                    communicator);
} // namespace hrcontact

#endif
