#include <deal.II/fe/fe.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/prolongation.h>

#include <functional>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  prolongate_to_finer_mesh(const DoFHandler<dim> &coarse_dofs,
                           const FieldVector     &coarse,
                           const DoFHandler<dim> &fine_dofs,
                           FieldVector           &fine)
  {
    const auto &fe = fine_dofs.get_fe();
    AssertThrow(coarse_dofs.get_fe() == fe,
                ExcMessage("prolongation between different elements"));
    AssertThrow(coarse_dofs.get_triangulation().n_cells(0) ==
                  fine_dofs.get_triangulation().n_cells(0),
                ExcMessage("prolongation between meshes of different coarse "
                           "grids"));
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       parent_values(n), values(n);
    std::vector<types::global_dof_index> dofs(n);

    using Cell = typename DoFHandler<dim>::cell_iterator;
    auto write = [&](const Cell &cell, const Vector<double> &v) {
      cell->get_dof_indices(dofs);
      for (unsigned int i = 0; i < n; ++i)
        if (fine.in_local_range(dofs[i]))
          fine(dofs[i]) = v[i];
    };
    // c and f are the same cell of the two meshes.
    std::function<void(const Cell &, const Cell &)> visit = [&](const Cell &c,
                                                                const Cell &f) {
      if (c->is_active())
        {
          if (c->is_artificial())
            return;
          c->get_dof_values(coarse, parent_values);
          if (f->is_active())
            {
              if (f->is_locally_owned())
                write(f, parent_values);
              return;
            }
          for (unsigned int k = 0; k < f->n_children(); ++k)
            {
              const Cell child = f->child(k);
              if (!child->is_active() || !child->is_locally_owned())
                continue;
              fe.get_prolongation_matrix(k, f->refinement_case())
                .vmult(values, parent_values);
              write(child, values);
            }
          return;
        }
      if (!f->has_children())
        {
          // Finer on the coarser mesh here (an adaptive cycle coarsened
          // it): Q1 vertex v of a cell is vertex v of its child v.
          if (!f->is_locally_owned() || fe.degree != 1)
            return;
          for (const unsigned int v : f->vertex_indices())
            {
              Cell d = c;
              while (!d->is_active())
                d = d->child(v);
              if (d->is_artificial())
                return;
              d->get_dof_values(coarse, parent_values);
              for (unsigned int k = 0; k < fe.n_components(); ++k)
                values[fe.component_to_system_index(k, v)] =
                  parent_values[fe.component_to_system_index(k, v)];
            }
          write(f, values);
          return;
        }
      for (unsigned int k = 0; k < c->n_children(); ++k)
        visit(c->child(k), f->child(k));
    };
    fine = 0;
    for (auto c = coarse_dofs.begin(0), f = fine_dofs.begin(0);
         c != coarse_dofs.end(0);
         ++c, ++f)
      visit(c, f);
    if (!is_complete(fine))
      fine.update_ghost_values();
  }

  template void
  prolongate_to_finer_mesh<2>(const DoFHandler<2> &,
                              const FieldVector &,
                              const DoFHandler<2> &,
                              FieldVector &);
  template void
  prolongate_to_finer_mesh<3>(const DoFHandler<3> &,
                              const FieldVector &,
                              const DoFHandler<3> &,
                              FieldVector &);
} // namespace hrcontact
