#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/postprocess/field_values.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  SymmetricTensor<2, dim>
  stress_tensor(const Vector<double> &components)
  {
    SymmetricTensor<2, dim> sigma;
    for (unsigned int c = 0; c < MixedSpaces<dim>::n_stress_components; ++c)
      {
        const auto ab = MixedSpaces<dim>::stress_component_indices(c);
        sigma[ab.first][ab.second] = components[c];
      }
    return sigma;
  }

  template <int dim>
  double
  von_mises(const SymmetricTensor<2, dim> &sigma, const double szz)
  {
    SymmetricTensor<2, 3> s3;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        s3[a][b] = sigma[a][b];
    if (dim == 2)
      s3[2][2] = szz;
    const SymmetricTensor<2, 3> dev = deviator(s3);
    return std::sqrt(1.5 * (dev * dev));
  }

  namespace
  {
    /** The quantity in the cell found around a point (unit coordinates). */
    template <int dim>
    double
    cell_value(const Results<dim>          &results,
               const std::pair<typename DoFHandler<dim>::active_cell_iterator,
                               Point<dim>> &found,
               const std::string           &quantity)
    {
      const MixedSpaces<dim> &spaces = results.spaces;
      const MappingQ1<dim>    mapping;
      const Quadrature<dim>   q(
        GeometryInfo<dim>::project_to_unit_cell(found.second));
      if (quantity[0] == 'u')
        {
          const unsigned int component = quantity[1] - 'x';
          typename DoFHandler<dim>::active_cell_iterator cell(
            &spaces.dof_handler_displacement.get_triangulation(),
            found.first->level(),
            found.first->index(),
            &spaces.dof_handler_displacement);
          FEValues<dim> fv(mapping, *spaces.fe_displacement, q, update_values);
          fv.reinit(cell);
          std::vector<Vector<double>> values(1, Vector<double>(dim));
          fv.get_function_values(results.displacement, values);
          return values[0][component];
        }
      FEValues<dim> fv(mapping, *spaces.fe_stress, q, update_values);
      fv.reinit(found.first);
      std::vector<Vector<double>> values(
        1, Vector<double>(MixedSpaces<dim>::n_stress_components));
      fv.get_function_values(results.stress, values);
      const auto sigma = stress_tensor<dim>(values[0]);
      if (quantity == "von_mises")
        return von_mises<dim>(
          sigma,
          results.scene.out_of_plane_stress(sigma, found.first->material_id()));
      const unsigned int a = quantity[1] - 'x', b = quantity[2] - 'x';
      if (a == 2 && dim == 2)
        return results.scene.out_of_plane_stress(sigma,
                                                 found.first->material_id());
      return sigma[a][b];
    }

    /** The cell of this process around the point (Q1 mapping) and the
     * point in its reference cell; end() where no own cell holds it. */
    template <typename MeshType>
    auto
    own_cell_around(const MeshType                   &mesh,
                    const Point<MeshType::dimension> &point)
    {
      decltype(GridTools::find_active_cell_around_point(
        MappingQ1<MeshType::dimension>(), mesh, point)) found;
      try
        {
          found = GridTools::find_active_cell_around_point(
            MappingQ1<MeshType::dimension>(), mesh, point);
        }
      catch (const std::exception &)
        {
          found.first = mesh.end();
        }
      if (found.first.state() != IteratorState::valid ||
          !found.first->is_locally_owned())
        found.first = mesh.end();
      return found;
    }
  } // namespace

  template <int dim>
  double
  point_value(const Results<dim> &results,
              const Point<dim>   &point,
              const std::string  &quantity)
  {
    const MixedSpaces<dim> &spaces = results.spaces;
    const auto        found = own_cell_around(spaces.dof_handler_stress, point);
    const bool        here  = found.first != spaces.dof_handler_stress.end();
    const std::string outside = "Postprocess/Probes: the point (" +
                                Utilities::to_string(point[0]) +
                                ", ...) is outside the mesh.";
    // A distributed mesh: the lowest process that owns a cell around the
    // point evaluates there and the sum hands the value to all. (On a face
    // between cells a discontinuous stress takes one side's value, on any
    // mesh.)
    if (const auto *parallel_mesh =
          dynamic_cast<const parallel::TriangulationBase<dim> *>(
            &spaces.dof_handler_stress.get_triangulation()))
      {
        const MPI_Comm     comm    = parallel_mesh->get_communicator();
        const unsigned int process = Utilities::MPI::this_mpi_process(comm);
        const unsigned int n       = Utilities::MPI::n_mpi_processes(comm);
        const unsigned int chosen =
          Utilities::MPI::min(here ? process : n, comm);
        if (chosen == n)
          throw InputError(outside);
        return Utilities::MPI::sum(
          chosen == process ? cell_value(results, found, quantity) : 0., comm);
      }
    if (!here)
      throw InputError(outside);
    return cell_value(results, found, quantity);
  }

  template <int dim>
  bool
  mesh_contains_point(const Triangulation<dim> &triangulation,
                      const Point<dim>         &point)
  {
    const bool here =
      own_cell_around(triangulation, point).first != triangulation.end();
    if (const auto *parallel_mesh =
          dynamic_cast<const parallel::TriangulationBase<dim> *>(
            &triangulation))
      return Utilities::MPI::max(here ? 1 : 0,
                                 parallel_mesh->get_communicator()) == 1;
    return here;
  }

  template <int dim>
  std::pair<double, double>
  stress_error(const MixedSpaces<dim> &spaces,
               const FieldVector      &s,
               const Function<dim>    &reference)
  {
    constexpr unsigned int      n_comp = MixedSpaces<dim>::n_stress_components;
    const QGauss<dim>           quadrature(3);
    FEValues<dim>               fv(*spaces.fe_stress,
                     quadrature,
                     update_values | update_quadrature_points |
                       update_JxW_values);
    std::vector<Vector<double>> values(quadrature.size(),
                                       Vector<double>(n_comp));
    Vector<double>              ref(n_comp);
    double max_err = 0, max_ref = 0, l2_err = 0, l2_ref = 0;
    for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fv.reinit(cell);
          fv.get_function_values(s, values);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              reference.vector_value(fv.quadrature_point(q), ref);
              const auto   sh = stress_tensor<dim>(values[q]);
              const auto   sr = stress_tensor<dim>(ref);
              const double e = (sh - sr).norm(), r = sr.norm();
              max_err = std::max(max_err, e);
              max_ref = std::max(max_ref, r);
              l2_err += e * e * fv.JxW(q);
              l2_ref += r * r * fv.JxW(q);
            }
        }
    // A distributed mesh: each process its own cells.
    if (const auto *parallel_mesh =
          dynamic_cast<const parallel::TriangulationBase<dim> *>(
            &spaces.dof_handler_stress.get_triangulation()))
      {
        const MPI_Comm comm = parallel_mesh->get_communicator();
        max_err             = Utilities::MPI::max(max_err, comm);
        max_ref             = Utilities::MPI::max(max_ref, comm);
        l2_err              = Utilities::MPI::sum(l2_err, comm);
        l2_ref              = Utilities::MPI::sum(l2_ref, comm);
      }
    return {max_ref > 0 ? max_err / max_ref : max_err,
            l2_ref > 0 ? std::sqrt(l2_err / l2_ref) : std::sqrt(l2_err)};
  }

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_reference_stress(ParameterHandler &prm, const Constants &constants)
  {
    const std::string text = prm.get("Reference stress");
    if (Utilities::trim(text).empty())
      return nullptr;
    return make_function<dim>(text,
                              MixedSpaces<dim>::n_stress_components,
                              constants,
                              "Postprocess/Reference stress");
  }

#define HRCONTACT_INSTANTIATE(dim)                                             \
  template SymmetricTensor<2, dim> stress_tensor<dim>(const Vector<double> &); \
  template double von_mises<dim>(const SymmetricTensor<2, dim> &,              \
                                 const double);                                \
  template double point_value<dim>(const Results<dim> &,                       \
                                   const Point<dim> &,                         \
                                   const std::string &);                       \
  template std::unique_ptr<FunctionParser<dim>> parse_reference_stress<dim>(   \
    ParameterHandler &, const Constants &);                                    \
  template bool mesh_contains_point<dim>(const Triangulation<dim> &,           \
                                         const Point<dim> &);                  \
  template std::pair<double, double> stress_error<dim>(                        \
    const MixedSpaces<dim> &, const FieldVector &, const Function<dim> &);
  HRCONTACT_INSTANTIATE(2)
  HRCONTACT_INSTANTIATE(3)
#undef HRCONTACT_INSTANTIATE
} // namespace hrcontact
