#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/discretisation/stress_constraint_field.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** Visits the points of the cells a process holds (owned and ghost,
     * or every cell of a serial mesh): (cell, owned, t, JxW, sigma). */
    template <int dim, typename Visitor>
    void
    for_each_point(const MixedSpaces<dim> &spaces,
                   const Quadrature<dim>  &rule,
                   const FieldVector      *stress,
                   const Visitor          &visit)
    {
      const FiniteElement<dim> &fe = *spaces.fe_stress;
      FEValues<dim>             fv(fe, rule, update_values | update_JxW_values);
      const unsigned int        n_s = fe.n_dofs_per_cell();
      Vector<double>            values(n_s);
      std::vector<SymmetricTensor<2, dim>> T(
        MixedSpaces<dim>::n_stress_components);
      for (unsigned int c = 0; c < T.size(); ++c)
        T[c] = MixedSpaces<dim>::stress_basis_tensor(c);
      std::vector<unsigned int> comp(n_s);
      for (unsigned int j = 0; j < n_s; ++j)
        comp[j] = fe.system_to_component_index(j).first;
      for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          fv.reinit(cell);
          if (stress)
            spaces.cell_values(cell, *stress, values);
          for (unsigned int t = 0; t < rule.size(); ++t)
            {
              SymmetricTensor<2, dim> sigma;
              if (stress)
                for (unsigned int j = 0; j < n_s; ++j)
                  sigma += values[j] * fv.shape_value(j, t) * T[comp[j]];
              visit(cell->active_cell_index(),
                    cell->is_locally_owned(),
                    t,
                    fv.JxW(t),
                    sigma);
            }
        }
    }

    template <int dim>
    MPI_Comm
    communicator(const MixedSpaces<dim> &spaces)
    {
      return spaces.dof_handler_stress.get_triangulation().get_communicator();
    }
  } // namespace

  template <int dim>
  StressConstraintField<dim>::StressConstraintField(
    const StressConstraint<dim> &constraint,
    const MixedSpaces<dim>      &spaces,
    const Points                 points)
    : constraint(constraint)
    , spaces(spaces)
    , rule(points == Points::vertices     ? Quadrature<dim>(QTrapezoid<dim>()) :
           points == Points::gauss_points ? Quadrature<dim>(QGauss<dim>(2)) :
                                            Quadrature<dim>(QGauss<dim>(1)))
  {
    const unsigned int n =
      spaces.dof_handler_stress.get_triangulation().n_active_cells() *
      rule.size();
    mu.assign(n, SymmetricTensor<2, dim>());
    weights.assign(n, 0.);
    for_each_point<dim>(spaces,
                        rule,
                        nullptr,
                        [&](const unsigned int cell,
                            const bool,
                            const unsigned int t,
                            const double       JxW,
                            const SymmetricTensor<2, dim> &) {
                          weights[cell * rule.size() + t] = JxW;
                        });
  }

  template <int dim>
  double
  StressConstraintField<dim>::update_multipliers(const FieldVector &stress)
  {
    double residual = 0;
    for_each_point<dim>(spaces,
                        rule,
                        &stress,
                        [&](const unsigned int cell,
                            const bool         owned,
                            const unsigned int t,
                            const double,
                            const SymmetricTensor<2, dim> &sigma) {
                          auto &m = mu[cell * rule.size() + t];
                          const SymmetricTensor<2, dim> next =
                            constraint.project(m + alpha * sigma);
                          if (owned)
                            residual =
                              std::max(residual, (next - m).norm() / alpha);
                          m = next;
                        });
    return Utilities::MPI::max(residual, communicator(spaces));
  }

  template <int dim>
  double
  StressConstraintField<dim>::largest_violation(const FieldVector &stress) const
  {
    double v = 0;
    for_each_point<dim>(spaces,
                        rule,
                        &stress,
                        [&](const unsigned int,
                            const bool owned,
                            const unsigned int,
                            const double,
                            const SymmetricTensor<2, dim> &sigma) {
                          if (owned)
                            v = std::max(v, constraint.violation(sigma));
                        });
    return Utilities::MPI::max(v, communicator(spaces));
  }

  template <int dim>
  double
  StressConstraintField<dim>::opening_at(const Point<dim> &point) const
  {
    const auto &tria = spaces.dof_handler_stress.get_triangulation();
    double      m    = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && cell->point_inside(point))
        for (unsigned int t = 0; t < rule.size(); ++t)
          m = std::max(m,
                       constraint.opening(
                         mu[cell->active_cell_index() * rule.size() + t]));
    return Utilities::MPI::max(m, communicator(spaces));
  }

  template <int dim>
  double
  StressConstraintField<dim>::largest_opening() const
  {
    double m = 0;
    for (const auto &x : mu)
      m = std::max(m, constraint.opening(x));
    return Utilities::MPI::max(m, communicator(spaces));
  }

  template <int dim>
  double
  StressConstraintField<dim>::cracked_fraction(const double threshold) const
  {
    const double largest = largest_opening();
    double       cracked = 0, total = 0;
    for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int t = 0; t < rule.size(); ++t)
          {
            const unsigned int i = cell->active_cell_index() * rule.size() + t;
            total += weights[i];
            if (largest > 0 && constraint.opening(mu[i]) > threshold * largest)
              cracked += weights[i];
          }
    cracked = Utilities::MPI::sum(cracked, communicator(spaces));
    total   = Utilities::MPI::sum(total, communicator(spaces));
    return total > 0 ? cracked / total : 0.;
  }

  template <int dim>
  Vector<float>
  StressConstraintField<dim>::cell_openings() const
  {
    const auto   &tria = spaces.dof_handler_stress.get_triangulation();
    Vector<float> openings(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (unsigned int t = 0; t < rule.size(); ++t)
          openings[cell->active_cell_index()] =
            std::max<float>(openings[cell->active_cell_index()],
                            constraint.opening(
                              mu[cell->active_cell_index() * rule.size() + t]));
    return openings;
  }

  template class StressConstraintField<2>;
  template class StressConstraintField<3>;
} // namespace hrcontact
