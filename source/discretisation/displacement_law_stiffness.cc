#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/displacement_law_stiffness.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;


  template <int dim>
  DisplacementLawStiffness<dim>::DisplacementLawStiffness(
    const Scene<dim>       &scene,
    const MixedSpaces<dim> &spaces)
    : scene(scene)
    , spaces(spaces)
  {
    const unsigned int n =
      spaces.dof_handler_displacement.get_triangulation().n_active_cells() *
      QGauss<dim>(2).size();
    stress.assign(n, SymmetricTensor<2, dim>());
    tangent.assign(n, SymmetricTensor<4, dim>());
  }

  template <int dim>
  unsigned int
  DisplacementLawStiffness<dim>::linearise_at(const FieldVector &u)
  {
    displacement.reinit(u, true);
    displacement.copy_locally_owned_data_from(u);
    if (!is_complete(u))
      displacement.update_ghost_values();
    const QGauss<dim>                    quadrature(2);
    const unsigned int                   nq = quadrature.size();
    FEValues<dim>                        fv(*spaces.fe_displacement,
                     quadrature,
                     update_gradients | update_quadrature_points);
    const FEValuesExtractors::Vector     displacements(0);
    std::vector<SymmetricTensor<2, dim>> eps(nq);
    // A point stops when its stress change is at most 1e-13 times the
    // largest stress of the last linearisation or its own (the first: only
    // its own).
    double scale = 0;
    for (const auto &s : stress)
      scale = std::max(scale, s.norm());
    unsigned int most_steps = 0;
    bool         failed     = false;
    Point<dim>   failed_at;
    for (const auto &cell :
         spaces.dof_handler_displacement.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        const MaterialLaw<dim> &law = scene.material_of(cell->material_id());
        fv.reinit(cell);
        fv[displacements].get_function_symmetric_gradients(displacement, eps);
        for (unsigned int q = 0; q < nq; ++q)
          {
            const std::size_t  k     = cell->active_cell_index() * nq + q;
            const Point<dim>  &x     = fv.quadrature_point(q);
            auto              &s     = stress[k];
            auto              &D     = tangent[k];
            unsigned int       steps = 0;
            double             last  = 0;
            const unsigned int limit = 50;
            for (; steps < limit; ++steps)
              {
                D = invert(compliance_tensor(law, s, x));
                const SymmetricTensor<2, dim> ds =
                  D * (law.strain(s, x) - eps[q]);
                s -= ds;
                last = ds.norm();
                if (last <= 1e-13 * std::max({scale, s.norm(), 1e-300}))
                  {
                    ++steps;
                    break;
                  }
              }
            // The tangent at the converged stress.
            D = invert(compliance_tensor(law, s, x));
            if ((steps >= limit &&
                 last > 1e-9 * std::max({scale, s.norm(), 1e-300})) ||
                !std::isfinite(s.norm()))
              {
                failed    = true;
                failed_at = x;
              }
            most_steps = std::max(most_steps, steps);
          }
      }
    const MPI_Comm comm =
      spaces.dof_handler_displacement.get_triangulation().get_communicator();
    if (Utilities::MPI::max(failed ? 1 : 0, comm) > 0)
      {
        std::ostringstream m;
        m << "Output/Compare with a displacement code: inverting the law";
        if (failed)
          m << " at (" << failed_at << ")";
        m << " for the stress of a strain did not converge in 50 local Newton "
             "steps.";
        throw NotConvergedError(m.str());
      }
    return Utilities::MPI::max(most_steps, comm);
  }

  template <int dim>
  void
  DisplacementLawStiffness<dim>::for_each_cell(
    const std::function<bool(unsigned int)> &filter,
    const Worker                            &worker) const
  {
    const auto        &fe = *spaces.fe_displacement;
    const QGauss<dim>  quadrature(2);
    const unsigned int nq = quadrature.size();
    FEValues<dim>      fv(fe, quadrature, update_gradients | update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    const FEValuesExtractors::Vector     displacements(0);
    FullMatrix<double>                   K(n, n);
    Vector<double>                       load(n), u_c(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, dim>> eps(n);
    for (const auto &cell :
         spaces.dof_handler_displacement.active_cell_iterators())
      {
        if (cell->is_artificial() || !filter(cell->active_cell_index()))
          continue;
        fv.reinit(cell);
        cell->get_dof_indices(dofs);
        K    = 0;
        load = 0;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const std::size_t k = cell->active_cell_index() * nq + q;
            for (unsigned int i = 0; i < n; ++i)
              eps[i] = fv[displacements].symmetric_gradient(i, q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const SymmetricTensor<2, dim> De = tangent[k] * eps[i];
                for (unsigned int j = 0; j < n; ++j)
                  K(i, j) += (De * eps[j]) * fv.JxW(q);
                load(i) -= (eps[i] * stress[k]) * fv.JxW(q);
              }
          }
        // K_c u_c - f_int,c: the step solves K u_new = f + K u - f_int.
        for (unsigned int i = 0; i < n; ++i)
          u_c(i) = displacement(dofs[i]);
        K.vmult_add(load, u_c);
        worker(cell->active_cell_index(), dofs, K, load);
      }
  }

  template class DisplacementLawStiffness<2>;
  template class DisplacementLawStiffness<3>;
} // namespace hrcontact
