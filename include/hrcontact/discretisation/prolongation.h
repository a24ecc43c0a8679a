#ifndef hrcontact_prolongation_h
#define hrcontact_prolongation_h

#include <deal.II/dofs/dof_handler.h>

#include <hrcontact/discretisation/field_vector.h>

namespace hrcontact
{
  /**
   * A field of a coarser mesh on a finer one made from the same coarse grid
   * (nested iteration: one global refinement more), for a first guess: each
   * owned fine cell takes its parent's values through the element's
   * prolongation matrices, or its own cell's where the two meshes agree.
   * The two meshes are walked together from their coarse cells, so that no
   * point is searched. Where the coarser mesh is finer instead (an
   * adaptive cycle coarsened there), a Q1 cell takes its descendants'
   * values at its vertices. Entries whose parent this process does not have (an
   * artificial cell of a distributed coarse mesh) stay zero: a first guess
   * only needs to be good, not complete. Both DoFHandlers carry the same
   * element; @p coarse has its ghost values (FieldVector); @p fine is sized
   * by reinit_field and gets its owned entries (and, distributed, its
   * ghosts).
   */
  template <int dim>
  void
  prolongate_to_finer_mesh(const dealii::DoFHandler<dim> &coarse_dofs,
                           const FieldVector             &coarse,
                           const dealii::DoFHandler<dim> &fine_dofs,
                           FieldVector                   &fine);
} // namespace hrcontact

#endif
