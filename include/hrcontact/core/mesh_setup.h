#ifndef hrcontact_mesh_setup_h
#define hrcontact_mesh_setup_h

#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/path_choice.h>
#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <memory>
#include <ostream>
#include <string>

namespace hrcontact
{
  /**
   * The mesh of a run and its distribution policy. Several processes on the
   * condensed path: a parallel::distributed::Triangulation, each process
   * keeping its own cells, a layer of ghost cells and the coarse mesh (as in
   * step-40). What needs every cell on every process keeps a serial mesh:
   * the dense null-space path (also when Path = automatic takes it for a
   * small mesh), a random distortion (p4est would distort each part
   * differently) and postprocessors that walk across the whole mesh.
   */
  template <int dim>
  class MeshSetup
  {
  public:
    explicit MeshSetup(const MPI_Comm communicator);

    /** What keeps the mesh serial besides its size. */
    struct Needs
    {
      bool postprocessor_walks_mesh = false;
      bool material_iteration       = false;
    };

    /** Build the mesh as the policy says, set up the spaces on it and
     * partition the displacement dofs and cells with p4est's order. */
    void
    create(const Scene<dim> &scene,
           MixedSpaces<dim> &spaces,
           const PathChoice &path_choice,
           const Needs      &needs,
           DofPartition     &partition);

    /** The mesh, the spaces and the partition, on `log`. */
    void
    describe(const Scene<dim>       &scene,
             const MixedSpaces<dim> &spaces,
             const DofPartition     &partition,
             std::ostream           &log) const;

    const dealii::Triangulation<dim> &
    triangulation() const;

    /** Whether the mesh is the distributed one. */
    bool
    distributed() const;

    /** The largest cell aspect ratio (AMG aggregation). */
    double
    largest_aspect_ratio() const;

  private:
    MPI_Comm communicator;
    /** Declared before the spaces of HRProblem, whose DoFHandlers refer to
     * it. */
    std::unique_ptr<dealii::Triangulation<dim>> mesh;
    bool                                        distributed_mesh = false;
    /** What keeps the mesh serial on several processes. */
    std::string replicated_reason;
    double      aspect_ratio = 1;
  };
} // namespace hrcontact

#endif
