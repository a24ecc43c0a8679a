#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/gauss_point_cone.h>
#include <hrcontact/discretisation/stress_constraint_field.h>
#include <hrcontact/material/linear_elasticity.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  GaussPointCone<dim>::GaussPointCone(const StressConstraint<dim> &constraint,
                                      const Scene<dim>            &scene,
                                      const MixedSpaces<dim>      &spaces,
                                      const double residual_stiffness)
    : constraint(constraint)
    , residual_stiffness(residual_stiffness)
    , scene(scene)
    , spaces(spaces)
    , T(MixedSpaces<dim>::n_stress_components)
  {
    // The point values must fix the stress field: DGQ1, one value per
    // Gauss point and component.
    const FiniteElement<dim> &base = spaces.fe_stress->base_element(0);
    const QGauss<dim>         points(2);
    if (spaces.has_parameters() || spaces.stress_element_name != "DGQ1" ||
        base.n_dofs_per_cell() != points.size())
      throw InputError(
        "Stress constraint iteration/Method = closed-form projection and "
        "interior point need Finite elements/Stress element = DGQ1 (its values at the "
        "2^dim Gauss points are its unknowns); '" +
        spaces.stress_element_name +
        "' is not that: set Method = augmented Lagrangian.");
    FullMatrix<double> values(points.size(), points.size());
    for (unsigned int t = 0; t < points.size(); ++t)
      for (unsigned int b = 0; b < points.size(); ++b)
        values(t, b) = base.shape_value(b, points.point(t));
    point_to_dof.reinit(points.size(), points.size());
    point_to_dof.invert(values);
    for (unsigned int c = 0; c < T.size(); ++c)
      T[c] = MixedSpaces<dim>::stress_basis_tensor(c);
    for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
      if (!cell->is_artificial())
        lame(cell->material_id());
  }

  template <int dim>
  std::pair<double, double>
  GaussPointCone<dim>::lame(const types::material_id body) const
  {
    const MaterialLaw<dim>      &law     = scene.material_of(body);
    const LinearElasticity<dim> *elastic = law.elastic_part();
    if (!elastic || !law.is_linear())
      throw InputError(
        "Stress constraint iteration/Method = closed-form projection and "
        "interior point need a linear elastic material (the projection onto "
        "the cone and its barrier are in closed form for it); for Ramberg-Osgood set Method = augmented "
        "Lagrangian.");
    const double E = elastic->youngs_modulus(), nu = elastic->poisson_ratio();
    const double G      = E / (2 * (1 + nu));
    double       lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    if (dim == 2 && !elastic->is_plane_strain())
      lambda = 2 * lambda * G / (lambda + 2 * G);
    return {lambda, G};
  }

  template <int dim>
  void
  GaussPointCone<dim>::linearise(const FieldVector &state)
  {
    const unsigned int n = n_points;
    linearised.resize(
      spaces.dof_handler_stress.get_triangulation().n_active_cells() * n);
    for_each_point(
      {&state},
      [&](const auto        &cell,
          const unsigned int t,
          const double,
          const std::vector<SymmetricTensor<2, dim>> &at) {
        PointModel &m = linearised[cell->active_cell_index() * n + t];
        point_stress(at[0], cell->material_id(), m.sigma, &m.tangent);
      });
  }

  template <int dim>
  const typename GaussPointCone<dim>::PointModel &
  GaussPointCone<dim>::linearised_at(const unsigned int cell,
                                     const unsigned int t) const
  {
    const std::size_t i = std::size_t(cell) * n_points + t;
    AssertThrow(i < linearised.size(),
                ExcMessage("GaussPointCone: the model is read before "
                           "linearise() was called"));
    return linearised[i];
  }

  template <int dim>
  void
  GaussPointCone<dim>::model(const unsigned int             cell,
                             const unsigned int             t,
                             const SymmetricTensor<2, dim> &eps,
                             SymmetricTensor<4, dim>       &F,
                             SymmetricTensor<2, dim>       &e) const
  {
    const PointModel &m = linearised_at(cell, t);
    F                   = invert(m.tangent);
    e                   = eps - F * m.sigma;
  }

  template <int dim>
  void
  GaussPointCone<dim>::point_stress(const SymmetricTensor<2, dim> &eps,
                                    const types::material_id       body,
                                    SymmetricTensor<2, dim>       &sigma,
                                    SymmetricTensor<4, dim> *tangent) const
  {
    const auto [lambda, G] = lame(body);
    if (barrier > 0)
      constraint.barrier_projection(
        eps, lambda, G, barrier, allowance, sigma, tangent, nullptr);
    else
      constraint.elastic_projection(eps, lambda, G, sigma, tangent, nullptr);
    if (tangent)
      {
        const auto I = unit_symmetric_tensor<dim>();
        *tangent += residual_stiffness * (lambda * outer_product(I, I) +
                                          2 * G * identity_tensor<dim>());
      }
  }

  template <int dim>
  template <typename Visitor>
  void
  GaussPointCone<dim>::for_each_point(
    const std::vector<const FieldVector *> &vectors,
    const Visitor                          &visit) const
  {
    const FiniteElement<dim> &fe = *spaces.fe_stress;
    const QGauss<dim>         points(2);
    FEValues<dim>             fv(fe, points, update_values | update_JxW_values);
    const unsigned int        n_s = fe.n_dofs_per_cell();
    std::vector<unsigned int> comp(n_s);
    for (unsigned int j = 0; j < n_s; ++j)
      comp[j] = fe.system_to_component_index(j).first;
    std::vector<Vector<double>> values(vectors.size(), Vector<double>(n_s));
    std::vector<SymmetricTensor<2, dim>> at(vectors.size());
    for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        fv.reinit(cell);
        for (unsigned int v = 0; v < vectors.size(); ++v)
          spaces.cell_values(cell, *vectors[v], values[v]);
        for (unsigned int t = 0; t < points.size(); ++t)
          {
            for (unsigned int v = 0; v < vectors.size(); ++v)
              {
                at[v] = 0;
                for (unsigned int j = 0; j < n_s; ++j)
                  at[v] += values[v][j] * fv.shape_value(j, t) * T[comp[j]];
              }
            visit(cell, t, fv.JxW(t), at);
          }
      }
  }

  template <int dim>
  void
  GaussPointCone<dim>::set_point_values(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const std::vector<SymmetricTensor<2, dim>>           &values,
    FieldVector                                          &v) const
  {
    const FiniteElement<dim>            &fe = *spaces.fe_stress;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(dofs);
    for (unsigned int j = 0; j < dofs.size(); ++j)
      {
        const auto [c, b] = fe.system_to_component_index(j);
        const auto pq     = MixedSpaces<dim>::stress_component_indices(c);
        double     x      = 0;
        for (unsigned int t = 0; t < values.size(); ++t)
          x += point_to_dof(b, t) * values[t][pq.first][pq.second];
        v(dofs[j]) = x;
      }
  }

  template <int dim>
  void
  GaussPointCone<dim>::strains_of_solve(const FieldVector &state,
                                        const FieldVector &stress,
                                        FieldVector       &strain) const
  {
    strain.reinit(state);
    const unsigned int                   n = QGauss<dim>(2).size();
    std::vector<SymmetricTensor<2, dim>> cell_strains(n);
    SymmetricTensor<4, dim>              F;
    SymmetricTensor<2, dim>              e;
    // Each cell this process holds (owned and ghost) is written whole, so
    // the ghost entries need no exchange.
    for_each_point({&state, &stress},
                   [&](const auto        &cell,
                       const unsigned int t,
                       const double,
                       const std::vector<SymmetricTensor<2, dim>> &at) {
                     model(cell->active_cell_index(), t, at[0], F, e);
                     cell_strains[t] = F * at[1] + e;
                     if (t + 1 == n)
                       set_point_values(cell, cell_strains, strain);
                   });
  }

  template <int dim>
  void
  GaussPointCone<dim>::strains_and_stresses(const FieldVector &u,
                                            const FieldVector &state,
                                            FieldVector       &strain,
                                            FieldVector       &stress) const
  {
    strain.reinit(state);
    stress.reinit(state);
    const DoFHandler<dim>           &dh_u = spaces.dof_handler_displacement;
    const FiniteElement<dim>        &fe_u = dh_u.get_fe();
    FEValues<dim>                    fv(fe_u, QGauss<dim>(2), update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<SymmetricTensor<2, dim>>           eps_u(n_points), s(n_points);
    typename DoFHandler<dim>::active_cell_iterator cu;
    for_each_point(
      {&state},
      [&](const auto        &cell,
          const unsigned int t,
          const double,
          const std::vector<SymmetricTensor<2, dim>> &at) {
        if (t == 0)
          {
            cu = typename DoFHandler<dim>::active_cell_iterator(
              &dh_u.get_triangulation(), cell->level(), cell->index(), &dh_u);
            fv.reinit(cu);
            fv[displacement].get_function_symmetric_gradients(u, eps_u);
          }
        const PointModel &m = linearised_at(cell->active_cell_index(), t);
        s[t]                = m.sigma + m.tangent * (eps_u[t] - at[0]);
        if (t + 1 == n_points)
          {
            set_point_values(cell, eps_u, strain);
            set_point_values(cell, s, stress);
          }
      });
  }

  template <int dim>
  std::pair<double, double>
  GaussPointCone<dim>::model_error(const FieldVector &stress,
                                   const FieldVector &strain) const
  {
    double error = 0, scale = 0;
    for_each_point({&stress, &strain},
                   [&](const auto &cell,
                       const unsigned int,
                       const double,
                       const std::vector<SymmetricTensor<2, dim>> &at) {
                     if (!cell->is_locally_owned())
                       return;
                     SymmetricTensor<2, dim> sigma;
                     point_stress(at[1], cell->material_id(), sigma, nullptr);
                     error = std::max(error, (sigma - at[0]).norm());
                     scale = std::max(scale, at[0].norm());
                   });
    const MPI_Comm comm =
      spaces.dof_handler_stress.get_triangulation().get_communicator();
    return {Utilities::MPI::max(error, comm), Utilities::MPI::max(scale, comm)};
  }

  template <int dim>
  double
  GaussPointCone<dim>::slope(const FieldVector &eps0,
                             const FieldVector &delta,
                             const double       theta,
                             double            *curvature) const
  {
    double s = 0, c = 0;
    for_each_point({&eps0, &delta},
                   [&](const auto                                 &cell,
                       const unsigned int                          t,
                       const double                                JxW,
                       const std::vector<SymmetricTensor<2, dim>> &at) {
                     if (!cell->is_locally_owned())
                       return;
                     const PointModel &m =
                       linearised_at(cell->active_cell_index(), t);
                     SymmetricTensor<2, dim> sigma = m.sigma;
                     if (theta != 0)
                       point_stress(at[0] + theta * at[1],
                                    cell->material_id(),
                                    sigma,
                                    nullptr);
                     s += JxW * (sigma * at[1]);
                     // The model's tangent D_q + eta C at eps0.
                     if (curvature)
                       c += JxW * (at[1] * (m.tangent * at[1]));
                   });
    const MPI_Comm comm =
      spaces.dof_handler_stress.get_triangulation().get_communicator();
    if (curvature)
      *curvature = Utilities::MPI::sum(c, comm);
    return Utilities::MPI::sum(s, comm);
  }

  template <int dim>
  void
  GaussPointCone<dim>::store_fracture_strains(
    const FieldVector          &strain,
    StressConstraintField<dim> &field) const
  {
    for_each_point(
      {&strain},
      [&](const auto        &cell,
          const unsigned int t,
          const double,
          const std::vector<SymmetricTensor<2, dim>> &at) {
        const auto [lambda, G] = lame(cell->material_id());
        SymmetricTensor<2, dim> sigma, mu;
        if (barrier > 0)
          constraint.barrier_projection(
            at[0], lambda, G, barrier, allowance, sigma, nullptr, &mu);
        else
          constraint.elastic_projection(at[0], lambda, G, sigma, nullptr, &mu);
        field.set_multiplier(cell->active_cell_index(), t, mu);
      });
  }

  template <int dim>
  double
  GaussPointCone<dim>::largest_strain(const FieldVector &strain) const
  {
    double m = 0;
    for_each_point({&strain},
                   [&](const auto &cell,
                       const unsigned int,
                       const double,
                       const std::vector<SymmetricTensor<2, dim>> &at) {
                     if (cell->is_locally_owned())
                       m = std::max(m, at[0].norm());
                   });
    return Utilities::MPI::max(
      m, spaces.dof_handler_stress.get_triangulation().get_communicator());
  }

  template class GaussPointCone<2>;
  template class GaussPointCone<3>;
} // namespace hrcontact
