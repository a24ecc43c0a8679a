#ifndef hrcontact_boundary_id_check_h
#define hrcontact_boundary_id_check_h

#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/scene.h>

#include <set>

namespace hrcontact
{
  /**
   * The boundary ids of the mesh's faces, over every process's cells
   * (collective on @p communicator: a distributed mesh knows only its own
   * part).
   */
  template <int dim>
  std::set<dealii::types::boundary_id>
  mesh_boundary_ids(const dealii::Triangulation<dim> &triangulation,
                    const MPI_Comm                    communicator);

  /**
   * Every boundary id a `.prm` entry names (Loads/Tractions, Loads/Projected
   * pressures and every constraint kind: supports, normal displacements,
   * obstacles, stops, contact pairs) must be on the mesh: a typo would
   * otherwise load nothing, or leave a mechanism that the solve reports
   * much later without pointing at the entry. Throws InputError naming the
   * entry, the id and the ids the mesh has, with the grid's names for them
   * (MeshGenerator::boundary_names). Collective, and every process throws
   * the same error.
   */
  template <int dim>
  void
  check_named_boundary_ids(const Scene<dim>                 &scene,
                           const dealii::Triangulation<dim> &triangulation,
                           const MPI_Comm                    communicator);
} // namespace hrcontact

#endif
