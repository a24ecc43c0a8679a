#ifndef hrcontact_contact_row_partition_h
#define hrcontact_contact_row_partition_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_noncontiguous_partitioner.h>

#include <hrcontact/discretisation/dof_partition.h>

#include <memory>
#include <vector>

namespace hrcontact
{
  struct EquilibriumSystem;

  /**
   * Which Q rows (indices into EquilibriumSystem::contact_rows) one MPI
   * process owns and which it sees, for the augmented Lagrangian of section
   * 4.4 (issue 17: each process owns the contact rows of its own nodes).
   *
   * A row belongs to the owner of its node (of the first dof of its
   * combination: a contact pair's slave node), the only process with every
   * cell around it, which therefore computes its p = Q s - q. A process
   * sees (relevant) the rows of its owned and ghost nodes: the held rows
   * among them are constraints on its relevant dofs. The rows of ghost nodes
   * get p from their owners point to point (import_ghosts), and every
   * process then runs the multiplier and penalty updates of its relevant
   * rows, the ghost rows' again, with the same operations on the same
   * numbers, so that no piece or multiplier is ever sent. Norms, counts and
   * decisions over all rows are reductions over the owned rows.
   *
   * With one process, on the null-space path and on a serial mesh that
   * every process solves whole, every row is owned and nothing is
   * communicated.
   */
  class ContactRowPartition
  {
  public:
    /** Every one of the n rows owned, no communication. */
    explicit ContactRowPartition(const unsigned int n_rows = 0);

    /** Rows by the owners of their nodes in `partition`. */
    ContactRowPartition(const EquilibriumSystem &system,
                        const DofPartition      &partition);

    unsigned int
    n_rows() const
    {
      return n;
    }
    /** The rows this process owns, increasing. */
    const std::vector<unsigned int> &
    owned() const
    {
      return owned_rows;
    }
    /** The rows of its owned and ghost nodes, increasing. */
    const std::vector<unsigned int> &
    relevant() const
    {
      return relevant_rows;
    }
    bool
    is_owned(const unsigned int i) const
    {
      return whole || owned_set.is_element(i);
    }
    /** Whether the rows live on several processes. */
    bool
    distributed() const
    {
      return !whole;
    }

    /** v (one entry per row) at the ghost rows from their owners. */
    void
    import_ghosts(std::vector<double> &v) const;

    /**
     * Every entry of v from the owner of its row, on every process: the
     * complete state for the results, gathered once per solve.
     */
    void
    gather(std::vector<double> &v) const;
    void
    gather(std::vector<bool> &v) const;

    /** Sums, extremes and agreements over the processes. */
    double
    sum(const double x) const;
    unsigned int
    sum(const unsigned int x) const;
    double
    max(const double x) const;
    double
    min(const double x) const;
    /** Whether x holds on every process. */
    bool
    all(const bool x) const;
    /** Element by element: whether x[j] holds on every process. */
    std::vector<bool>
    all(const std::vector<bool> &x) const;

    /** sqrt of the sum over the owned rows of v_i^2. */
    double
    norm(const std::vector<double> &v) const;

  private:
    unsigned int              n            = 0;
    bool                      whole        = true;
    MPI_Comm                  communicator = MPI_COMM_SELF;
    dealii::IndexSet          owned_set;
    std::vector<unsigned int> owned_rows, relevant_rows, ghost_rows;
    /** Sends the owned rows' values to the processes that see them. */
    std::shared_ptr<dealii::Utilities::MPI::NoncontiguousPartitioner> exchange;
  };
} // namespace hrcontact

#endif
