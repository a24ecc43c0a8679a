#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/postprocess/section_forces.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** The stress tensor of the discrete field at a point of a cell. */
    SymmetricTensor<2, 2>
    stress_at(const MixedSpaces<2>                      &spaces,
              const FieldVector                         &stress,
              const DoFHandler<2>::active_cell_iterator &cell,
              const Point<2>                            &unit_point,
              std::vector<types::global_dof_index>      &dofs)
    {
      const auto &fe = *spaces.fe_stress;
      cell->get_dof_indices(dofs);
      SymmetricTensor<2, 2> sigma;
      for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
        {
          const unsigned int c = fe.system_to_component_index(j).first;
          sigma += stress(dofs[j]) * fe.shape_value(j, unit_point) *
                   MixedSpaces<2>::stress_basis_tensor(c);
        }
      return sigma;
    }

    Tensor<1, 2>
    displacement_at(const MixedSpaces<2>                      &spaces,
                    const FieldVector                         &displacement,
                    const DoFHandler<2>::active_cell_iterator &stress_cell,
                    const Point<2>                            &unit_point)
    {
      const DoFHandler<2>::active_cell_iterator cell(
        &spaces.dof_handler_displacement.get_triangulation(),
        stress_cell->level(),
        stress_cell->index(),
        &spaces.dof_handler_displacement);
      const auto                          &fe = *spaces.fe_displacement;
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      cell->get_dof_indices(dofs);
      Tensor<1, 2> u;
      for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
        u[fe.system_to_component_index(j).first] +=
          displacement(dofs[j]) * fe.shape_value(j, unit_point);
      return u;
    }

    struct Piece
    {
      double                              start, end;
      DoFHandler<2>::active_cell_iterator cell;
    };

    /**
     * The pieces of the line P + xi nu in each (convex) cell it crosses,
     * sorted by xi; @p length_scale: the largest such cell's diameter.
     */
    std::vector<Piece>
    pieces_along_line(const MixedSpaces<2> &spaces,
                      const Point<2>       &P,
                      const Tensor<1, 2>   &nu,
                      double               &length_scale)
    {
      const Tensor<1, 2> tau({nu[1], -nu[0]});
      std::vector<Piece> pieces;
      for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
        {
          static constexpr unsigned int order[4] = {0, 1, 3, 2};
          const double                  h        = cell->diameter();
          double                        d[4], d_min = 0, d_max = 0;
          for (unsigned int k = 0; k < 4; ++k)
            {
              d[k] = (cell->vertex(order[k]) - P) * tau;
              if (std::abs(d[k]) < 1e-12 * h)
                d[k] = 0; // the line runs through this vertex
              d_min = (k == 0) ? d[k] : std::min(d_min, d[k]);
              d_max = (k == 0) ? d[k] : std::max(d_max, d[k]);
            }
          if (d_min > 0 || d_max < 0)
            continue;
          double lo = std::numeric_limits<double>::max(),
                 hi = -std::numeric_limits<double>::max();
          for (unsigned int k = 0; k < 4; ++k)
            {
              const Point<2> &a  = cell->vertex(order[k]);
              const Point<2> &b  = cell->vertex(order[(k + 1) % 4]);
              const double    da = d[k], db = d[(k + 1) % 4];
              auto            take = [&](const Point<2> &x) {
                const double xi = (x - P) * nu;
                lo              = std::min(lo, xi);
                hi              = std::max(hi, xi);
              };
              if (da == 0)
                take(a);
              if ((da < 0 && db > 0) || (da > 0 && db < 0))
                take(a + (da / (da - db)) * (b - a));
            }
          if (hi - lo > 1e-10 * h)
            {
              pieces.push_back({lo, hi, cell});
              length_scale = std::max(length_scale, h);
            }
        }
      std::sort(pieces.begin(),
                pieces.end(),
                [](const Piece &a, const Piece &b) {
                  return a.start < b.start;
                });
      return pieces;
    }

    std::vector<SectionForce>
    section_forces_2d(const MixedSpaces<2>              &spaces,
                      const FieldVector                 &stress,
                      const FieldVector                 &displacement,
                      const std::vector<SectionStation> &stations)
    {
      const auto     &mapping = StaticMappingQ1<2>::mapping;
      const QGauss<1> gauss(4);
      std::vector<types::global_dof_index> dofs(
        spaces.fe_stress->n_dofs_per_cell());
      std::vector<SectionForce> results;
      for (const SectionStation &station : stations)
        {
          const Tensor<1, 2> nu = station.across / station.across.norm();
          const Tensor<1, 2> tau({nu[1], -nu[0]});
          const Point<2>    &P = station.point;

          // Clip the line P + xi nu against each (convex) cell.
          double                   length_scale = 0;
          const std::vector<Piece> pieces =
            pieces_along_line(spaces, P, nu, length_scale);
          // The connected run of pieces that contains xi = 0.
          const double tol   = 1e-9 * length_scale;
          int          first = -1;
          unsigned int last  = 0;
          double       reach = 0;
          for (unsigned int k = 0; k < pieces.size();)
            {
              unsigned int l = k;
              double       r = pieces[k].end;
              while (l + 1 < pieces.size() && pieces[l + 1].start <= r + tol)
                r = std::max(r, pieces[++l].end);
              if (pieces[k].start <= tol && r >= -tol)
                {
                  first = k;
                  last  = l;
                  reach = r;
                  break;
                }
              k = l + 1;
            }
          if (first < 0)
            {
              std::ostringstream s;
              s << "Postprocess: the section station at (" << P
                << ") lies outside the body.";
              throw InputError(s.str());
            }

          SectionForce result;
          result.station      = station;
          const double xi_in  = pieces[first].start;
          const double xi_out = reach;
          const double xi_c   = 0.5 * (xi_in + xi_out);
          result.inner        = P + xi_in * nu;
          result.outer        = P + xi_out * nu;
          result.centre       = P + xi_c * nu;
          result.thickness    = xi_out - xi_in;
          double covered      = xi_in;
          for (unsigned int k = first; k <= last; ++k)
            {
              const double a = std::max(pieces[k].start, covered);
              const double b = pieces[k].end;
              if (!(b > a + tol))
                continue;
              covered = b;
              for (unsigned int q = 0; q < gauss.size(); ++q)
                {
                  const double   xi = a + (b - a) * gauss.point(q)[0];
                  const double   w  = (b - a) * gauss.weight(q);
                  const Point<2> x  = P + xi * nu;
                  const Point<2> unit =
                    mapping.transform_real_to_unit_cell(pieces[k].cell, x);
                  const auto sigma =
                    stress_at(spaces, stress, pieces[k].cell, unit, dofs);
                  const double s_tt = tau * (sigma * tau);
                  const double s_tn = nu * (sigma * tau);
                  result.N += s_tt * w;
                  result.V += s_tn * w;
                  result.M -= (xi - xi_c) * s_tt * w;
                }
              // Face values and the centre displacement from the cell that
              // holds them.
              auto value_at = [&](const double xi) {
                const Point<2> unit =
                  mapping.transform_real_to_unit_cell(pieces[k].cell,
                                                      P + xi * nu);
                return std::make_pair(
                  tau * (stress_at(spaces, stress, pieces[k].cell, unit, dofs) *
                         tau),
                  unit);
              };
              if (a <= xi_in + tol)
                result.sigma_inner = value_at(xi_in).first;
              if (b >= xi_out - tol)
                result.sigma_outer = value_at(xi_out).first;
              if (a <= xi_c + tol && b >= xi_c - tol)
                result.displacement = displacement_at(spaces,
                                                      displacement,
                                                      pieces[k].cell,
                                                      value_at(xi_c).second);
            }
          results.push_back(result);
        }
      return results;
    }
  } // namespace

  template <int dim>
  std::vector<SectionForce>
  compute_section_forces(const MixedSpaces<dim>            &spaces,
                         const FieldVector                 &stress,
                         const FieldVector                 &displacement,
                         const std::vector<SectionStation> &stations)
  {
    if (!is_complete(stress))
      throw InputError("Postprocess: section forces need the stresses of "
                       "the whole mesh (a serial mesh).");
    if constexpr (dim == 2)
      return section_forces_2d(spaces, stress, displacement, stations);
    else
      throw InputError("Postprocess: section forces are computed in 2D only.");
  }

  template <int dim>
  std::array<double, 4>
  principal_stress_extremes(const MixedSpaces<dim> &spaces,
                            const FieldVector      &stress,
                            const Point<dim>       &exclude_centre,
                            const double            exclude_radius)
  {
    if (!is_complete(stress))
      throw InputError("Postprocess: principal stress extremes need the "
                       "stresses of the whole mesh (a serial mesh).");
    if constexpr (dim != 2)
      throw InputError("Postprocess: principal stress extremes are computed "
                       "in 2D only.");
    else
      {
        std::array<double, 4> e = {{std::numeric_limits<double>::max(),
                                    -std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::max(),
                                    -std::numeric_limits<double>::max()}};
        std::vector<types::global_dof_index> dofs(
          spaces.fe_stress->n_dofs_per_cell());
        for (const auto &cell :
             spaces.dof_handler_stress.active_cell_iterators())
          for (const auto v : cell->vertex_indices())
            if (!(cell->center().distance(exclude_centre) < exclude_radius))
              {
                const auto sigma =
                  stress_at(spaces,
                            stress,
                            cell,
                            GeometryInfo<2>::unit_cell_vertex(v),
                            dofs);
                const auto ev = eigenvalues(sigma); // descending
                e[0]          = std::min(e[0], ev[1]);
                e[1]          = std::max(e[1], ev[1]);
                e[2]          = std::min(e[2], ev[0]);
                e[3]          = std::max(e[3], ev[0]);
              }
        return e;
      }
  }

  template std::vector<SectionForce>
  compute_section_forces(const MixedSpaces<2> &,
                         const FieldVector &,
                         const FieldVector &,
                         const std::vector<SectionStation> &);
  template std::vector<SectionForce>
  compute_section_forces(const MixedSpaces<3> &,
                         const FieldVector &,
                         const FieldVector &,
                         const std::vector<SectionStation> &);
  template std::array<double, 4>
  principal_stress_extremes(const MixedSpaces<2> &,
                            const FieldVector &,
                            const Point<2> &,
                            double);
  template std::array<double, 4>
  principal_stress_extremes(const MixedSpaces<3> &,
                            const FieldVector &,
                            const Point<3> &,
                            double);
} // namespace hrcontact
