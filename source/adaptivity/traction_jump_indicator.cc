#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/adaptivity/traction_jump_indicator.h>
#include <hrcontact/postprocess/field_values.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** The stress tensor at each quadrature point of a face values object
     * reinitialised on a stress cell's face or subface. */
    template <int dim, typename FaceValues>
    std::vector<SymmetricTensor<2, dim>>
    stresses(const FaceValues &values, const FieldVector &stress)
    {
      std::vector<Vector<double>> components(values.n_quadrature_points,
                                             Vector<double>(
                                               values.get_fe().n_components()));
      values.get_function_values(stress, components);
      std::vector<SymmetricTensor<2, dim>> sigma;
      for (const auto &c : components)
        sigma.push_back(stress_tensor<dim>(c));
      return sigma;
    }

    /** The quadrature point of @p others nearest to @p x. */
    template <int dim>
    unsigned int
    nearest(const std::vector<Point<dim>> &others, const Point<dim> &x)
    {
      unsigned int best = 0;
      for (unsigned int k = 1; k < others.size(); ++k)
        if (others[k].distance(x) < others[best].distance(x))
          best = k;
      return best;
    }
  } // namespace

  template <int dim>
  void
  TractionJumpIndicator<dim>::estimate(const Results<dim> &results,
                                       Vector<float>      &indicators) const
  {
    const auto           &dh    = results.spaces.dof_handler_stress;
    const auto           &fe    = dh.get_fe();
    const Scene<dim>     &scene = results.scene;
    const QGauss<dim - 1> rule(2);
    const auto            flags = update_values | update_quadrature_points |
                       update_normal_vectors | update_JxW_values;
    FEFaceValues<dim>    own_face(fe, rule, flags), other_face(fe, rule, flags);
    FESubfaceValues<dim> own_subface(fe, rule, flags),
      other_subface(fe, rule, flags);
    Vector<double> applied(dim);

    // Half of h int |(sigma_own - sigma_other) n|^2 over the face, the
    // other side's stresses at the matching points.
    auto jump = [&](const auto &own, const auto &other) {
      const auto sigma       = stresses<dim>(own, results.stress);
      const auto sigma_other = stresses<dim>(other, results.stress);
      double     sum = 0, area = 0;
      for (unsigned int q = 0; q < own.n_quadrature_points; ++q)
        {
          const unsigned int o = nearest<dim>(other.get_quadrature_points(),
                                              own.quadrature_point(q));
          sum +=
            ((sigma[q] - sigma_other[o]) * own.normal_vector(q)).norm_square() *
            own.JxW(q);
          area += own.JxW(q);
        }
      return 0.5 * std::pow(area, 1. / (dim - 1)) * sum;
    };

    indicators.reinit(results.triangulation().n_active_cells());
    for (const auto &cell : dh.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        double eta2 = 0;
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              {
                const types::boundary_id id   = cell->face(f)->boundary_id();
                bool                     held = false;
                for (const auto &source : scene.constraints)
                  held = held || source->acts_on(id);
                if (held)
                  continue;
                own_face.reinit(cell, f);
                const auto sigma = stresses<dim>(own_face, results.stress);
                double     sum = 0, area = 0;
                for (unsigned int q = 0; q < sigma.size(); ++q)
                  {
                    const Point<dim>     &x = own_face.quadrature_point(q);
                    const Tensor<1, dim> &n = own_face.normal_vector(q);
                    Tensor<1, dim>        t;
                    if (const auto it = scene.tractions.find(id);
                        it != scene.tractions.end())
                      {
                        it->second->vector_value(x, applied);
                        for (unsigned int d = 0; d < dim; ++d)
                          t[d] = applied[d];
                      }
                    if (const auto it = scene.projected_pressures.find(id);
                        it != scene.projected_pressures.end())
                      {
                        it->second->vector_value(x, applied);
                        for (unsigned int d = 0; d < dim; ++d)
                          t[d] -= applied[d] * n[d];
                      }
                    sum += (sigma[q] * n - t).norm_square() * own_face.JxW(q);
                    area += own_face.JxW(q);
                  }
                eta2 += std::pow(area, 1. / (dim - 1)) * sum;
              }
            else if (cell->face(f)->has_children())
              {
                // Finer neighbours: each small face from both sides.
                for (unsigned int sf = 0; sf < cell->face(f)->n_children();
                     ++sf)
                  {
                    const auto child = cell->neighbor_child_on_subface(f, sf);
                    own_subface.reinit(cell, f, sf);
                    other_face.reinit(child, cell->neighbor_of_neighbor(f));
                    eta2 += jump(own_subface, other_face);
                  }
              }
            else if (cell->neighbor_is_coarser(f))
              {
                const auto [face, subface] =
                  cell->neighbor_of_coarser_neighbor(f);
                own_face.reinit(cell, f);
                other_subface.reinit(cell->neighbor(f), face, subface);
                eta2 += jump(own_face, other_subface);
              }
            else
              {
                own_face.reinit(cell, f);
                other_face.reinit(cell->neighbor(f),
                                  cell->neighbor_of_neighbor(f));
                eta2 += jump(own_face, other_face);
              }
          }
        indicators[cell->active_cell_index()] = std::sqrt(eta2);
      }
  }

  template class TractionJumpIndicator<2>;
  template class TractionJumpIndicator<3>;

  HRCONTACT_REGISTER_REFINEMENT_INDICATOR(
    TractionJumpIndicator,
    "traction jump",
    "the jump of the discontinuous stresses' normal traction across faces, "
    "and their misfit to the applied traction on free and loaded "
    "boundaries: what only a stress formulation has")
} // namespace hrcontact
