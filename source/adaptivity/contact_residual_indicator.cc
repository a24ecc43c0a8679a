#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <hrcontact/adaptivity/contact_residual_indicator.h>
#include <hrcontact/adaptivity/traction_jump_indicator.h>
#include <hrcontact/postprocess/contact_fields.h>
#include <hrcontact/postprocess/field_values.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  ContactResidualIndicator<dim>::estimate(const Results<dim> &results,
                                          Vector<float>      &indicators) const
  {
    TractionJumpIndicator<dim>().estimate(results, indicators);
    // The compliance that turns a squared traction times an area into an
    // energy (isotropic: the same for every direction e).
    SymmetricTensor<2, dim> ee;
    ee[0][0]              = 1;
    const auto compliance = [&](const auto &cell) {
      return ee *
             results.scene.material_of(cell->material_id())
               .compliance_times(SymmetricTensor<2, dim>(), ee, cell->center());
    };
    if (!results.contact)
      {
        for (const auto &cell : results.triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            indicators[cell->active_cell_index()] *=
              std::sqrt(compliance(cell));
        return;
      }

    const ContactFields<dim> fields(results);
    const auto              &contact_dh = fields.get_dof_handler();
    const auto              &dh         = results.spaces.dof_handler_stress;
    const QGauss<dim - 1>    rule(2);
    FEFaceValues<dim>        stress_face(dh.get_fe(),
                                  rule,
                                  update_values | update_normal_vectors |
                                    update_JxW_values),
      contact_face(contact_dh.get_fe(), rule, update_values);
    const unsigned int          nq = rule.size();
    std::vector<Vector<double>> components(
      nq, Vector<double>(dh.get_fe().n_components()));
    std::vector<double> p(nq), gap(nq);
    Vector<double>      status(contact_dh.get_fe().n_dofs_per_cell());
    for (const auto &cell : dh.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const typename DoFHandler<dim>::active_cell_iterator contact_cell(
          &results.triangulation(), cell->level(), cell->index(), &contact_dh);
        const unsigned int i    = cell->active_cell_index();
        const double       c    = compliance(cell);
        double             eta2 = c * indicators[i] * indicators[i];
        contact_cell->get_dof_values(fields.get_status(), status);
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            // A contact face: every node has a contact row (status >= 1).
            bool all = true;
            for (const unsigned int v : cell->face(f)->vertex_indices())
              all &=
                status[GeometryInfo<dim>::face_to_cell_vertices(f, v)] >= 1;
            if (!all)
              continue;
            stress_face.reinit(cell, f);
            contact_face.reinit(contact_cell, f);
            stress_face.get_function_values(results.stress, components);
            contact_face.get_function_values(fields.get_pressure(), p);
            contact_face.get_function_values(fields.get_gap(), gap);
            double misfit = 0, complementarity = 0, area = 0;
            for (unsigned int q = 0; q < nq; ++q)
              {
                const Tensor<1, dim> &n = stress_face.normal_vector(q);
                misfit += (stress_tensor<dim>(components[q]) * n + p[q] * n)
                            .norm_square() *
                          stress_face.JxW(q);
                complementarity += std::abs(p[q] * gap[q]) * stress_face.JxW(q);
                area += stress_face.JxW(q);
              }
            eta2 +=
              c * std::pow(area, 1. / (dim - 1)) * misfit + 2 * complementarity;
          }
        indicators[i] = std::sqrt(eta2);
      }
  }

  template class ContactResidualIndicator<2>;
  template class ContactResidualIndicator<3>;

  HRCONTACT_REGISTER_REFINEMENT_INDICATOR(
    ContactResidualIndicator,
    "contact residual",
    "the traction jump in energy units, plus on contact faces the misfit of "
    "the stresses' traction to the nodal pressure and the complementarity "
    "term 2 int p (g - u_n) of the Prager-Synge bound, which marks the edge "
    "of the contact zone")
} // namespace hrcontact
