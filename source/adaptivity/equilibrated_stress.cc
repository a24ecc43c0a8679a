#include <deal.II/base/mpi.h>

#include <hrcontact/adaptivity/cell_equilibration.h>
#include <hrcontact/adaptivity/contact_row_kinds.h>
#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/adaptivity/face_tractions.h>
#include <hrcontact/adaptivity/hexahedron_bound.h>
#include <hrcontact/adaptivity/triangle_split.h>
#include <hrcontact/core/input.h>
#include <hrcontact/postprocess/field_values.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  EquilibratedStress<dim>::check_scene(const Scene<dim> &scene)
  {
    const std::string what =
      "The error bound (Postprocess/Error bound, Mesh refinement/Estimator = "
      "bound, Target error)";
    if (dim == 3)
      for (unsigned int body = 0; body < std::max(1u, scene.n_bodies); ++body)
        if (!scene.material_of(body).is_linear())
          throw InputError(what + " covers linear elastic bodies only in 3D "
                                  "so far.");
    // u_h must meet every constraint pointwise where it meets it at the
    // nodes (prescribed displacements, point supports, straight obstacles:
    // ContactTractions carries their reactions).
    for (const auto &source : scene.constraints)
      if (!source->holds_pointwise_from_nodes())
        throw InputError(what + " does not cover " + source->entry() +
                         " yet (of the contact and normal kinds only "
                         "Contact/Obstacles, straight, along whose faces the "
                         "gap is linear; Contact/Contact pairs on meshes that "
                         "match across a straight interface; "
                         "Supports/Normal displacements along an axis).");
    if (scene.stress_constraint)
      throw InputError(what + " does not cover Admissible stresses yet (a "
                              "reconstruction inside the cone).");
    // A nonlinear law needs its complementary potential (the Fenchel-Young
    // gap).
    for (unsigned int body = 0; body < std::max(1u, scene.n_bodies); ++body)
      if (std::isnan(scene.material_of(body).complementary_energy(
            SymmetricTensor<2, dim>(), Point<dim>())))
        throw InputError(what + " needs a law that gives its complementary "
                                "potential (linear elasticity, "
                                "Ramberg-Osgood).");
  }

  template <int dim>
  void
  EquilibratedStress<dim>::check_rows(const EquilibriumSystem &system)
  {
    const std::string what =
      "The error bound (Postprocess/Error bound, Mesh refinement/Estimator = "
      "bound, Target error)";
    if (const std::string why = ContactRowKinds::not_covered(system);
        !why.empty())
      throw InputError(what + " covers " + why + ".");
    for (const auto &row : system.rows)
      if (row.row_class == RowClass::prescribed && single_dof(row) < 0)
        throw InputError(what + " covers prescribed displacement components "
                                "only (no normal or rotated constraints).");
  }

  template <int dim>
  EquilibratedStress<dim>::EquilibratedStress(const Results<dim> &results)
    : results(results)
  {
    check_scene(results.scene);
    check_rows(results.system);
    if constexpr (dim == 3)
      if (const std::string why = HexahedronBound::not_covered(results);
          !why.empty())
        throw InputError("The error bound (Postprocess/Error bound, Mesh "
                         "refinement/Estimator = bound, Target error) covers " +
                         why + ".");
  }

  template <int dim>
  double
  EquilibratedStress<dim>::bound() const
  {
    double s = 0;
    for (const double b : bound_squared)
      s += b;
    s = Utilities::MPI::sum(s, results.partition.communicator);
    if (lift == 0)
      return std::sqrt(s);
    // v = u_h + w meets the contact rows: |u - u_h| <= |u - v| + |w|_E and
    // |tau - C eps(v)| <= |tau - C eps(u_h)| + |w|_E.
    const double quadratic = std::sqrt(std::max(0., s - contact_term));
    return std::sqrt(std::pow(quadratic + lift, 2) + contact_term) + lift;
  }

  template <int dim>
  void
  EquilibratedStress<dim>::compute()
  {
    if constexpr (dim == 2)
      {
        const FaceTractions faces(results);
        CellEquilibration   cells(results, faces);
        traction_residual = faces.residual;
        coefficients.assign(results.triangulation().n_active_cells(),
                            Vector<double>());
        bound_squared.assign(coefficients.size(), 0.);
        solution_energy = 0;
        for (const auto &cell :
             results.spaces.dof_handler_displacement.active_cell_iterators())
          if (results.partition.owned_cell[cell->active_cell_index()])
            {
              double energy = 0;
              cells.solve(cell,
                          coefficients[cell->active_cell_index()],
                          bound_squared[cell->active_cell_index()],
                          energy);
              solution_energy += energy;
            }
        const MPI_Comm comm = results.partition.communicator;
        cell_residual       = Utilities::MPI::max(cells.residual, comm);
        solution_energy     = Utilities::MPI::sum(solution_energy, comm);
        add_contact_terms(faces);
      }
    else
      {
        bound_squared.assign(results.triangulation().n_active_cells(), 0.);
        hexahedra = std::make_shared<HexahedronBound>(results);
        hexahedra->compute(bound_squared,
                           solution_energy,
                           traction_residual,
                           cell_residual);
      }
  }

  template <int dim>
  void
  EquilibratedStress<dim>::add_contact_terms(const FaceTractions &faces)
  {
    contact_term = lift             = 0;
    const ContactTractions *contact = faces.contact();
    if (!contact)
      return;
    for (const auto &cell : results.triangulation().active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        for (const unsigned int f : cell->face_indices())
          if (const auto *c = contact->find(cell->face(f)->index()))
            {
              const double term =
                ContactTractions::gap_term(*c, cell->face(f)->measure());
              bound_squared[cell->active_cell_index()] += term;
              contact_term += term;
            }
    const MPI_Comm comm = results.partition.communicator;
    contact_term        = Utilities::MPI::sum(contact_term, comm);
    lift = std::sqrt(Utilities::MPI::sum(contact->lift_energy_squared, comm));
    largest_penetration =
      Utilities::MPI::max(contact->largest_penetration, comm);
  }

  template <int dim>
  typename EquilibratedStress<dim>::Comparison
  EquilibratedStress<dim>::compare(const Function<dim> &reference) const
  {
    Comparison result;
    if constexpr (dim == 2)
      {
        const TrianglePolynomials polynomials(CellEquilibration::degree);
        CellSampler               sampler(results);
        Vector<double>            ref(MixedSpaces<dim>::n_stress_components);
        for (const auto &cell :
             results.spaces.dof_handler_displacement.active_cell_iterators())
          if (results.partition.owned_cell[cell->active_cell_index()])
            {
              const TriangleSplit split(cell);
              // More points than the bound's rule: the reference field is not
              // a polynomial.
              const unsigned int    n_tri = split.parallelogram() ? 6 : 10;
              std::vector<Point<2>> points;
              std::vector<double>   weights;
              split.rule(n_tri, points, weights);
              std::vector<SymmetricTensor<2, dim>> eps, sigma_h;
              sampler(cell, split, points, eps, sigma_h);
              const auto &law = results.scene.material_of(cell->material_id());
              // C eps(u_h): the law gives C^-1; invert it on the components.
              FullMatrix<double> C(3, 3);
              C.invert(component_compliance(law));
              const auto elastic_stress = [&](const SymmetricTensor<2, 2> &e) {
                const double          ev[3] = {e[0][0], e[1][1], 2 * e[0][1]};
                SymmetricTensor<2, 2> s;
                for (unsigned int b = 0; b < 3; ++b)
                  {
                    s[0][0] += C(0, b) * ev[b];
                    s[1][1] += C(1, b) * ev[b];
                    s[0][1] += C(2, b) * ev[b];
                  }
                return s;
              };
              const auto energy = [&](const SymmetricTensor<2, dim> &s) {
                return s * law.strain(s, Point<dim>());
              };
              // A nonlinear law: twice the Bregman distances of phi^c,
              // which are |.|^2 / 2 for a linear one.
              const auto bregman = [&](const SymmetricTensor<2, dim> &a,
                                       const SymmetricTensor<2, dim> &b,
                                       const Point<dim>              &p) {
                return 2 * (law.complementary_energy(a, p) -
                            law.complementary_energy(b, p) -
                            (a - b) * law.strain(b, p));
              };
              for (unsigned int q = 0; q < points.size(); ++q)
                {
                  reference.vector_value(points[q], ref);
                  const auto sigma = stress_tensor<dim>(ref);
                  const auto tau =
                    polynomials.stress(coefficients[cell->active_cell_index()],
                                       split,
                                       q / (n_tri * n_tri),
                                       points[q]);
                  const double w = weights[q];
                  if (law.is_linear())
                    {
                      const auto Ceps = elastic_stress(eps[q]);
                      result.displacement_error_squared +=
                        w * energy(sigma - Ceps);
                      result.reconstruction_error_squared +=
                        w * energy(sigma - tau);
                      result.stress_error_squared +=
                        w * energy(sigma - sigma_h[q]);
                      result.reference_energy_squared += w * energy(sigma);
                      continue;
                    }
                  // W(eps_h) - W(eps) - sigma : (eps_h - eps) = the Bregman
                  // distance of phi^c from W'(eps_h) to sigma.
                  const SymmetricTensor<2, dim> s_h =
                    stress_at_strain(law, eps[q], points[q], &sigma_h[q]);
                  result.displacement_error_squared +=
                    w * bregman(sigma, s_h, points[q]);
                  result.reconstruction_error_squared +=
                    w * bregman(tau, sigma, points[q]);
                  result.stress_error_squared +=
                    w * bregman(sigma_h[q], sigma, points[q]);
                  result.reference_energy_squared +=
                    w * 2 * law.complementary_energy(sigma, points[q]);
                }
            }
      }
    else
      {
        Assert(hexahedra, ExcMessage("compute() first"));
        const auto sums                     = hexahedra->compare(reference);
        result.displacement_error_squared   = sums[0];
        result.reconstruction_error_squared = sums[1];
        result.stress_error_squared         = sums[2];
        result.reference_energy_squared     = sums[3];
      }
    const MPI_Comm comm = results.partition.communicator;
    for (double *v : {&result.displacement_error_squared,
                      &result.reconstruction_error_squared,
                      &result.stress_error_squared,
                      &result.reference_energy_squared})
      *v = Utilities::MPI::sum(*v, comm);
    return result;
  }

  template class EquilibratedStress<2>;
  template class EquilibratedStress<3>;
} // namespace hrcontact
