#include <deal.II/fe/fe_q.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/mixed_spaces.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  MixedSpaces<dim>::MixedSpaces() = default;

  template <int dim>
  void
  MixedSpaces<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite elements");
    prm.declare_entry("Stress element",
                      "DGQ1",
                      Patterns::Anything(),
                      "The discontinuous stress field of a cell. " +
                        StressElementFactory<dim>::documentation() + ".");
    prm.leave_subsection();
  }

  template <int dim>
  void
  MixedSpaces<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite elements");
    stress_element_name = prm.get("Stress element");
    prm.leave_subsection();
  }

  template <int dim>
  void
  MixedSpaces<dim>::setup(const Triangulation<dim> &triangulation)
  {
    fe_displacement = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim);
    stress_element =
      StressElementFactory<dim>::create(Utilities::trim(stress_element_name));
    fe_stress            = stress_element->value_element();
    fe_stress_parameters = stress_element->parameter_element();

    dof_handler_displacement.reinit(triangulation);
    dof_handler_displacement.distribute_dofs(*fe_displacement);
    dof_handler_stress.reinit(triangulation);
    dof_handler_stress.distribute_dofs(*fe_stress);
    dof_handler_stress_parameters.reinit(triangulation);
    if (fe_stress_parameters)
      dof_handler_stress_parameters.distribute_dofs(*fe_stress_parameters);
  }

  template <int dim>
  void
  MixedSpaces<dim>::cell_expansion(
    const typename Triangulation<dim>::cell_iterator &cell,
    FullMatrix<double>                               &T) const
  {
    stress_element->expansion(cell, *fe_stress, T);
  }

  template <int dim>
  void
  MixedSpaces<dim>::cell_values(
    const typename Triangulation<dim>::cell_iterator &cell,
    const FieldVector                                &unknowns,
    Vector<double>                                   &values) const
  {
    const DoFHandler<dim>                               &dh = stress_unknowns();
    const typename DoFHandler<dim>::active_cell_iterator dof_cell(
      &dh.get_triangulation(), cell->level(), cell->index(), &dh);
    const unsigned int                   n_p = dh.get_fe().n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n_p);
    dof_cell->get_dof_indices(dofs);
    values.reinit(fe_stress->n_dofs_per_cell());
    if (!fe_stress_parameters)
      {
        for (unsigned int j = 0; j < n_p; ++j)
          values[j] = unknowns[dofs[j]];
        return;
      }
    Vector<double> beta(n_p);
    for (unsigned int j = 0; j < n_p; ++j)
      beta[j] = unknowns[dofs[j]];
    FullMatrix<double> T;
    cell_expansion(cell, T);
    T.vmult(values, beta);
  }

  template <int dim>
  void
  MixedSpaces<dim>::expand(const FieldVector &unknowns,
                           FieldVector       &values) const
  {
    if (!fe_stress_parameters)
      {
        values = unknowns;
        return;
      }
    Vector<double>                       local;
    std::vector<types::global_dof_index> dofs(fe_stress->n_dofs_per_cell());
    for (const auto &cell : dof_handler_stress.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_values(cell, unknowns, local);
          cell->get_dof_indices(dofs);
          for (unsigned int j = 0; j < dofs.size(); ++j)
            values[dofs[j]] = local[j];
        }
    if (!is_complete(values))
      values.update_ghost_values();
  }

  template <int dim>
  std::pair<unsigned int, unsigned int>
  MixedSpaces<dim>::stress_component_indices(const unsigned int c)
  {
    if (c < dim)
      return {c, c};
    if (dim == 2)
      return {0, 1};
    static const std::pair<unsigned int, unsigned int> off[3] = {{0, 1},
                                                                 {0, 2},
                                                                 {1, 2}};
    return off[c - dim];
  }

  template <int dim>
  SymmetricTensor<2, dim>
  MixedSpaces<dim>::stress_basis_tensor(const unsigned int c)
  {
    const auto              ab = stress_component_indices(c);
    SymmetricTensor<2, dim> t;
    t[ab.first][ab.second] = 1.; // symmetric storage sets (b,a) as well
    return t;
  }

  template <int dim>
  std::string
  MixedSpaces<dim>::stress_component_name(const unsigned int c)
  {
    const char *xyz = "xyz";
    const auto  ab  = stress_component_indices(c);
    return std::string("s") + xyz[ab.first] + xyz[ab.second];
  }

  template class MixedSpaces<2>;
  template class MixedSpaces<3>;
} // namespace hrcontact
