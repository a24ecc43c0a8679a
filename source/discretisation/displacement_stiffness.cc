#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/discretisation/displacement_stiffness.h>
#include <hrcontact/material/linear_elasticity.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  DisplacementStiffness<dim>::DisplacementStiffness(
    const Scene<dim>       &scene,
    const MixedSpaces<dim> &spaces)
    : spaces(spaces)
  {
    // A nonlinear law: the elastic solve of its elastic part.
    for (unsigned int body = 0; body < scene.n_bodies; ++body)
      {
        const LinearElasticity<dim> *law =
          scene.material_of(body).elastic_part();
        if (!law)
          throw InputError("Output/Time the Q1 floor: the floor is a linear "
                           "elastic displacement solve; Material/Model names "
                           "a law without a linear elastic part.");
        const double E = law->youngs_modulus(), nu = law->poisson_ratio();
        mu.push_back(E / (2 * (1 + nu)));
        // Plane stress: sigma_zz = 0 condenses lambda to 2 lambda mu /
        // (lambda + 2 mu) = E nu / (1 - nu^2), finite at nu = 1/2 (which
        // plane stress allows) where lambda itself is not.
        lambda.push_back((dim == 2 && !law->is_plane_strain()) ?
                           E * nu / (1 - nu * nu) :
                           E * nu / ((1 + nu) * (1 - 2 * nu)));
      }
  }

  template <int dim>
  void
  DisplacementStiffness<dim>::for_each_cell(
    const std::function<bool(unsigned int)> &filter,
    const Worker                            &worker) const
  {
    const auto        &fe = *spaces.fe_displacement;
    const QGauss<dim>  quadrature(2);
    FEValues<dim>      fv(fe, quadrature, update_gradients | update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> K(n, n);
    const Vector<double>                 no_load;
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, dim>> eps(n);
    std::vector<double>                  div(n);
    for (const auto &cell :
         spaces.dof_handler_displacement.active_cell_iterators())
      {
        if (!filter(cell->active_cell_index()))
          continue;
        fv.reinit(cell);
        cell->get_dof_indices(dofs);
        // One body: whatever material ids the grid generator set.
        const unsigned int body = this->mu.size() > 1 ? cell->material_id() : 0;
        const double       lambda = this->lambda.at(body);
        const double       mu     = this->mu.at(body);
        K                         = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int   a = fe.system_to_component_index(i).first;
                const Tensor<1, dim> g = fv.shape_grad(i, q);
                eps[i]                 = 0;
                for (unsigned int b = 0; b < dim; ++b)
                  eps[i][a][b] = (a == b) ? g[a] : 0.5 * g[b];
                div[i] = g[a];
              }
            // sigma = lambda tr(eps) I + 2 mu eps.
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                K(i, j) +=
                  (lambda * div[i] * div[j] + 2 * mu * (eps[i] * eps[j])) *
                  fv.JxW(q);
          }
        worker(cell->active_cell_index(), dofs, K, no_load);
      }
  }

  template class DisplacementStiffness<2>;
  template class DisplacementStiffness<3>;
} // namespace hrcontact
