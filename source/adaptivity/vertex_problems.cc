#include <deal.II/lac/lapack_full_matrix.h>

#include <hrcontact/adaptivity/vertex_problems.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::vector<bool>
  cells_held_whole(const Results<dim> &results)
  {
    std::vector<bool> usable(results.triangulation().n_active_cells(), false);
    std::vector<types::global_dof_index> dofs;
    const auto holds = [](const FieldVector &v, const auto &indices) {
      for (const auto i : indices)
        if (!v.in_local_range(i) && !v.get_partitioner()->is_ghost_entry(i))
          return false;
      return true;
    };
    for (const auto &cell :
         results.spaces.dof_handler_stress.active_cell_iterators())
      if (!cell->is_artificial())
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          bool ok = holds(results.stress, dofs);
          const typename DoFHandler<dim>::active_cell_iterator u_cell(
            &results.triangulation(),
            cell->level(),
            cell->index(),
            &results.spaces.dof_handler_displacement);
          dofs.resize(u_cell->get_fe().n_dofs_per_cell());
          u_cell->get_dof_indices(dofs);
          usable[cell->active_cell_index()] =
            ok && holds(results.displacement, dofs);
        }
    return usable;
  }

  template <int dim>
  Tensor<1, dim>
  data_traction(const Scene<dim>        &scene,
                const types::boundary_id id,
                const Point<dim>        &x,
                const Tensor<1, dim>    &normal)
  {
    Tensor<1, dim> t;
    Vector<double> v(dim);
    if (const auto it = scene.tractions.find(id); it != scene.tractions.end())
      {
        it->second->vector_value(x, v);
        for (unsigned int d = 0; d < dim; ++d)
          t[d] += v[d];
      }
    if (const auto it = scene.projected_pressures.find(id);
        it != scene.projected_pressures.end())
      {
        it->second->vector_value(x, v);
        for (unsigned int d = 0; d < dim; ++d)
          t[d] -= v[d] * normal[d];
      }
    return t;
  }

  template Tensor<1, 2>
  data_traction(const Scene<2> &,
                const types::boundary_id,
                const Point<2> &,
                const Tensor<1, 2> &);
  template Tensor<1, 3>
  data_traction(const Scene<3> &,
                const types::boundary_id,
                const Point<3> &,
                const Tensor<1, 3> &);

  template std::vector<bool>
  cells_held_whole(const Results<2> &);
  template std::vector<bool>
  cells_held_whole(const Results<3> &);

  const FullMatrix<double> &
  VertexProblemInverses::operator()(const std::vector<signed char> &key)
  {
    // Kept per sign pattern (n, m, then A row by row): most vertices share
    // one of a few.
    auto it = inverses.find(key);
    if (it == inverses.end())
      {
        const unsigned int       n = key[0], m = key[1];
        LAPACKFullMatrix<double> pinv(n, m);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < m; ++j)
            pinv(i, j) = key[2 + i * m + j];
        pinv.compute_inverse_svd(1e-12);
        FullMatrix<double> P(m, n);
        Vector<double>     unit(n), column(m);
        for (unsigned int i = 0; i < n; ++i)
          {
            unit    = 0;
            unit(i) = 1;
            pinv.vmult(column, unit);
            for (unsigned int j = 0; j < m; ++j)
              P(j, i) = column(j);
          }
        it = inverses.emplace(key, std::move(P)).first;
      }
    return it->second;
  }

} // namespace hrcontact
