#ifndef hrcontact_field_vector_h
#define hrcontact_field_vector_h

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/la_parallel_vector.h>

namespace hrcontact
{
  /**
   * A field of the results (the stresses), indexed by global dof either way:
   * on a parallel::distributed::Triangulation this process's share only, the
   * dofs it owns (those of its own cells) and, as ghosts, those of its ghost
   * cells, as in step-40; on a serial mesh every entry on every process, even
   * under MPI (the tunnel's section lines and the null-space path need the
   * whole field). A global vector on every process cost 8 bytes a stress dof
   * each (75 MB at Hertz refinement 9, 390 MB on the 3D block at 3.2M dofs).
   */
  using FieldVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /** Size v for the DoFHandler's mesh: distributed or complete (above),
   * zeroed. */
  template <int dim>
  void
  reinit_field(FieldVector &v, const dealii::DoFHandler<dim> &dof_handler);

  /** @p to becomes a copy of @p from: its layout, owned values and ghosts. */
  inline void
  copy_field(const FieldVector &from, FieldVector &to)
  {
    to.reinit(from, true);
    to.copy_locally_owned_data_from(from);
    to.update_ghost_values();
  }

  /** Whether the entries of v are finite on every process (collective):
   * a diverged solve is stopped before any result file is written. */
  bool
  all_finite(const FieldVector &v);

  /** Sum a complete vector over the processes of @p communicator, each of
   * which filled its own entries and left zeros elsewhere (a field of a
   * serial mesh under MPI, gathered on every process). */
  void
  sum_over_processes(FieldVector &v, const MPI_Comm communicator);

  /** Whether v holds every entry on this process (a serial mesh). */
  inline bool
  is_complete(const FieldVector &v)
  {
    return !dealii::Utilities::MPI::job_supports_mpi() ||
           dealii::Utilities::MPI::n_mpi_processes(v.get_mpi_communicator()) ==
             1;
  }
} // namespace hrcontact

#endif
