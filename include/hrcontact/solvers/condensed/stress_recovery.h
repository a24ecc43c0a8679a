#ifndef hrcontact_condensed_stress_recovery_h
#define hrcontact_condensed_stress_recovery_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/hanging_nodes.h>

#include <memory>
#include <vector>

namespace hrcontact
{
  /**
   * The stresses of the condensed path from its displacements, cell by cell:
   * s_c = F_c^{-1} (B_c^T u - d_c) (section 4.2; d_c a material Newton
   * step's strain term), and from them p = Q s - q of the Q rows, the
   * reactions every Newton step returns.
   *
   * Every step needs only the recovery cells (the system's stored cells:
   * those of the Q and H rows on a lean system, or all), whose F_c^{-1}
   * B_c^T are kept; their stresses are stored cell after cell, a surface
   * instead of a vector of every stress dof of the mesh on every process
   * (75 MB at Hertz refinement 9, 98 MB on the 3D block at 807k dofs). The
   * other cells' stresses are recomputed from their blocks when the whole
   * field is asked for (stresses()).
   */
  class StressRecovery
  {
  public:
    StressRecovery(const EquilibriumSystem &system,
                   const DofPartition      &partition);

    /** Forget the cells, before the cells are passed again; @p complete:
     * whether every cell will be a recovery cell. */
    void
    clear(const unsigned int n_recovery_cells, const bool complete);

    /** The next recovery cell: its F_c^{-1} B_c^T and, from a material
     * Newton step, its F_c^{-1} d_c (else empty). */
    void
    add_cell(const unsigned int                cell,
             const dealii::FullMatrix<double> &recovery,
             const dealii::Vector<double>     &shift);

    /**
     * Lay out the recovered stresses and index the terms of p. With
     * @p with_rows false (a stiffness that is not B F^-1 B^T: the Q1
     * floor) p is not computed.
     */
    void
    index(const bool with_rows);

    /** The recovery cells' stresses from u (the relevant dofs). */
    void
    recover(const FieldVector &u);

    /** p = Q s - q of the Q rows @p rows owns, and of its ghost rows from
     * their owners. */
    void
    contact_reactions(const ContactRowPartition &rows,
                      std::vector<double>       &p) const;

    /**
     * The stresses of this process's cells into @p stress: the recovery
     * cells' from the last recover(), the others recomputed from u; the
     * ghosts from their owners, or summed over the processes into a
     * complete vector (a serial mesh under MPI).
     */
    void
    stresses(const FieldVector &u, FieldVector &stress) const;

  private:
    const EquilibriumSystem &system;
    const DofPartition      &partition;

    std::vector<unsigned int>               cells;
    std::vector<dealii::FullMatrix<double>> recovery;
    /** Whether cells holds every cell. */
    bool complete = true;
    /** The stress dofs of the cells added so far. */
    std::size_t n_added = 0;
    /** Cell k's stresses from offset[k]. */
    std::vector<double>      stress;
    std::vector<std::size_t> offset;
    /** F_c^{-1} d_c, laid out as stress; empty for a linear law. */
    std::vector<double> shift;
    /**
     * p = Q s - q without a global stress vector: for each Q row this
     * process owns, its terms (the index k into the row's combination, the
     * position in `stress`, the entry of B) in the order of
     * EquilibriumSystem::row_times, so that the sums are the same to the
     * last bit; the row's coefficients are read at each step (rows that
     * follow the configuration change them). Rows term_start[i] to
     * term_start[i + 1].
     */
    struct StressTerm
    {
      unsigned int k;
      std::size_t  position;
      double       b;
    };
    std::vector<StressTerm>  terms;
    std::vector<std::size_t> term_start;
    /** A locally refined mesh: the hanging shares' forces (summed over the
     * processes at each step) and each of their terms' position in
     * `stress`; null on a uniform mesh. */
    mutable std::unique_ptr<HangingShareForces> share_forces;
    std::vector<std::size_t>                    share_position;
  };
} // namespace hrcontact

#endif
