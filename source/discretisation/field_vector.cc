#include <deal.II/dofs/dof_tools.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/discretisation/field_vector.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  reinit_field(FieldVector &v, const DoFHandler<dim> &dof_handler)
  {
    if (const auto *mesh =
          dynamic_cast<const parallel::DistributedTriangulationBase<dim> *>(
            &dof_handler.get_triangulation()))
      {
        IndexSet relevant;
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
        v.reinit(dof_handler.locally_owned_dofs(),
                 relevant,
                 mesh->get_communicator());
      }
    else
      v.reinit(dof_handler.n_dofs());
  }

  void
  sum_over_processes(FieldVector &v, const MPI_Comm communicator)
  {
    const ArrayView<const double> values(v.begin(), v.size());
    const ArrayView<double>       sums(v.begin(), v.size());
    Utilities::MPI::sum(values, communicator, sums);
  }

  bool
  all_finite(const FieldVector &v)
  {
    bool finite = true;
    for (const double x : v)
      finite &= std::isfinite(x);
    return Utilities::MPI::min(int(finite), v.get_mpi_communicator()) == 1;
  }

  template void
  reinit_field<2>(FieldVector &, const DoFHandler<2> &);
  template void
  reinit_field<3>(FieldVector &, const DoFHandler<3> &);
} // namespace hrcontact
