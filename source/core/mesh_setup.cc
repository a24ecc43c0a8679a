#include <deal.II/base/utilities.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/core/boundary_id_check.h>
#include <hrcontact/core/mesh_setup.h>
#include <hrcontact/geometry/cell_aspect_ratio.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  MeshSetup<dim>::MeshSetup(const MPI_Comm communicator)
    : communicator(communicator)
  {}

  template <int dim>
  void
  MeshSetup<dim>::create(const Scene<dim> &scene,
                         MixedSpaces<dim> &spaces,
                         const PathChoice &path_choice,
                         const Needs      &needs,
                         DofPartition     &partition)
  {
    using Setting = PathChoice::Setting;
    const unsigned int n_processes =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(communicator) :
        1;
    replicated_reason =
      path_choice.setting == Setting::null_space ? "the null-space path" :
      scene.distortion != 0                      ? "Geometry/Distortion" :
      needs.postprocessor_walks_mesh ? "a postprocessor walks across it" :
                                       "";
    distributed_mesh = n_processes > 1 && replicated_reason.empty();
    if (n_processes > 1 && !distributed_mesh && scene.refined_locally())
      throw InputError("Mesh refinement: a locally refined mesh runs on "
                       "several processes only as a distributed mesh, which " +
                       replicated_reason +
                       " keeps from it; run it on one process.");
    if (distributed_mesh)
      mesh = std::make_unique<parallel::distributed::Triangulation<dim>>(
        communicator);
    else
      // The 2:1 balance at vertices p4est keeps on a distributed mesh, so
      // that a locally refined mesh is the same serially.
      mesh = std::make_unique<Triangulation<dim>>(
        Triangulation<dim>::limit_level_difference_at_vertices);
    scene.create_mesh(*mesh);
    check_named_boundary_ids(scene, *mesh, communicator);
    spaces.setup(*mesh);
    // Path = automatic takes the dense null-space path where it fits: a
    // mesh that small stays serial, as it needs every cell on every process
    // (the mesh is cheap to build again).
    if (distributed_mesh && path_choice.setting == Setting::automatic &&
        !needs.material_iteration && !scene.refined_locally() &&
        path_choice.dense_fits_every_dof_free(
          spaces.dof_handler_displacement.n_dofs(),
          spaces.stress_unknowns().n_dofs()))
      {
        distributed_mesh  = false;
        replicated_reason = "small enough for the null-space path";
        // The DoFHandlers move to the new mesh before the old one goes.
        auto serial = std::make_unique<Triangulation<dim>>(
          Triangulation<dim>::limit_level_difference_at_vertices);
        scene.create_mesh(*serial);
        spaces.setup(*serial);
        mesh = std::move(serial);
      }
    partition = partition_with_p4est(*mesh,
                                     spaces.dof_handler_displacement,
                                     communicator);
    // Stretched cells change how AMG should coarsen (AMG aggregation).
    aspect_ratio = largest_cell_aspect_ratio(*mesh);
  }

  template <int dim>
  void
  MeshSetup<dim>::describe(const Scene<dim>       &scene,
                           const MixedSpaces<dim> &spaces,
                           const DofPartition     &partition,
                           std::ostream           &log) const
  {
    log << "  "
        << (dim == 2 ? "2D (" + scene.plane_condition_name() + ")" : "3D")
        << ", stress element " << spaces.stress_element_name << '\n'
        << "  mesh: " << mesh->n_global_active_cells() << " cells, "
        << spaces.dof_handler_displacement.n_dofs() / dim << " nodes\n"
        << "  dofs: " << spaces.dof_handler_displacement.n_dofs()
        << " displacement, " << spaces.stress_unknowns().n_dofs() << " stress"
        << (spaces.has_parameters() ? " parameters" : "") << std::endl;
    if (partition.distributed())
      log << "  parallel: " << partition.describe()
          << (distributed_mesh ?
                ", distributed mesh" :
                ", replicated mesh (" + replicated_reason + ")")
          << std::endl;
  }

  template <int dim>
  const Triangulation<dim> &
  MeshSetup<dim>::triangulation() const
  {
    return *mesh;
  }

  template <int dim>
  bool
  MeshSetup<dim>::distributed() const
  {
    return distributed_mesh;
  }

  template <int dim>
  double
  MeshSetup<dim>::largest_aspect_ratio() const
  {
    return aspect_ratio;
  }

  template class MeshSetup<2>;
  template class MeshSetup<3>;
} // namespace hrcontact
