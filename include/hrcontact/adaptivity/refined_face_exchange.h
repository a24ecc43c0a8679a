#ifndef hrcontact_refined_face_exchange_h
#define hrcontact_refined_face_exchange_h

#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <map>

namespace hrcontact
{
  /**
   * Values kept per half of a face that a hanging node splits (by the
   * half's line index, two numbers each), sent from the process that owns
   * the coarse cell to every process that holds that cell as a ghost
   * (GridTools::exchange_cell_data_to_ghosts). FaceTractions needs it: a
   * parent vertex's patch holds the coarse cell, not always both fine
   * cells, so only the coarse cell's owner is sure to solve the hanging
   * node. Nothing to do on one process; a receiver whose fine side of the
   * face is artificial (the face is whole there) skips it.
   */
  void
  exchange_from_coarse_cells(
    const dealii::Triangulation<2>                &triangulation,
    const MPI_Comm                                 communicator,
    std::map<unsigned int, std::array<double, 2>> &values);
} // namespace hrcontact

#endif
