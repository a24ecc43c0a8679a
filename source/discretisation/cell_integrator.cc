#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/cell_integrator.h>
#include <hrcontact/discretisation/gauss_point_cone.h>
#include <hrcontact/discretisation/stress_constraint_field.h>

#include <cmath>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  CellIntegrator<dim>::CellIntegrator(
    const Scene<dim>                 &scene,
    const MixedSpaces<dim>           &spaces,
    const FieldVector                *stress_state,
    const StressConstraintField<dim> *constraint_field,
    const GaussPointCone<dim>        *cone)
    : scene(scene)
    , spaces(spaces)
    , stress_state(stress_state)
    , constraint_field(constraint_field)
    , cone(cone)
    , parameters(spaces.has_parameters())
    , n_p(spaces.stress_unknowns().get_fe().n_dofs_per_cell())
    , quadrature(2)
    , face_quadrature(2)
    , fv_u(*spaces.fe_displacement,
           quadrature,
           update_gradients | update_values | update_quadrature_points |
             update_JxW_values)
    , fv_s(*spaces.fe_stress, quadrature, update_values)
    , fv_face(*spaces.fe_displacement,
              face_quadrature,
              update_values | update_quadrature_points | update_normal_vectors |
                update_JxW_values)
    , n_u(spaces.fe_displacement->n_dofs_per_cell())
    , n_s(spaces.fe_stress->n_dofs_per_cell())
    , K(n_comp, n_comp)
    , T(n_comp)
    , comp_u(n_u)
    , comp_s(n_s)
    , pq_s(n_s)
    , psi(n_s)
    , s_loc(n_s)
    , beta(n_p)
    , Fc(parameters ? &F_values : &blocks.F)
    , Bc(parameters ? &B_values : &blocks.B)
    , force(dim)
    , pressure(dim)
    , may_reuse(!stress_state && !constraint_field && !cone)
    , previous_body(numbers::invalid_material_id)
    , K_vertex(n_comp, n_comp)
  {
    const auto &fe_u = *spaces.fe_displacement;
    const auto &fe_s = *spaces.fe_stress;
    for (unsigned int c = 0; c < n_comp; ++c)
      T[c] = MixedSpaces<dim>::stress_basis_tensor(c);
    // Looked up once, not in the n_s^2 and n_u n_s loops below (same sums
    // in the same order).
    for (unsigned int i = 0; i < n_u; ++i)
      comp_u[i] = fe_u.system_to_component_index(i).first;
    for (unsigned int j = 0; j < n_s; ++j)
      {
        comp_s[j] = fe_s.system_to_component_index(j).first;
        pq_s[j]   = MixedSpaces<dim>::stress_component_indices(comp_s[j]);
      }
    blocks.displacement_dofs.resize(n_u);
    blocks.stress_dofs.resize(n_p);
    Bc->reinit(n_u, n_s);
    Fc->reinit(n_s, n_s);
    blocks.load.reinit(n_u);
    if (constraint_field)
      fv_vertex =
        std::make_unique<FEValues<dim>>(fe_s,
                                        constraint_field->quadrature(),
                                        update_values | update_JxW_values);
  }

  template <int dim>
  void
  CellIntegrator<dim>::read_stress_state(const cell_iterator &cs)
  {
    const auto &ds = blocks.stress_dofs;
    if (parameters)
      spaces.cell_expansion(cs, T_c);
    if (!stress_state)
      return;
    if (parameters)
      {
        for (unsigned int j = 0; j < n_p; ++j)
          beta[j] = (*stress_state)[ds[j]];
        T_c.vmult(s_loc, beta);
      }
    else
      for (unsigned int j = 0; j < n_s; ++j)
        s_loc[j] = (*stress_state)[ds[j]];
  }

  template <int dim>
  void
  CellIntegrator<dim>::body_force_term(const unsigned int q, const double JxW)
  {
    if (!scene.body_force)
      return;
    scene.body_force->vector_value(fv_u.quadrature_point(q), force);
    for (unsigned int i = 0; i < n_u; ++i)
      blocks.load(i) += fv_u.shape_value(i, q) * force(comp_u[i]) * JxW;
  }

  template <int dim>
  void
  CellIntegrator<dim>::compliance_term(const unsigned int, const double JxW)
  {
    // Terms with a zero compliance factor add nothing.
    for (unsigned int i = 0; i < n_s; ++i)
      {
        const unsigned int ci    = comp_s[i];
        const double       psi_i = psi[i];
        for (unsigned int j = 0; j < n_s; ++j)
          {
            const double k = K(ci, comp_s[j]);
            if (k != 0)
              (*Fc)(i, j) += psi_i * psi[j] * k * JxW;
          }
      }
  }

  template <int dim>
  void
  CellIntegrator<dim>::equilibrium_term(const unsigned int q, const double JxW)
  {
    for (unsigned int i = 0; i < n_u; ++i)
      {
        const unsigned int   a    = comp_u[i];
        const Tensor<1, dim> grad = fv_u.shape_grad(i, q);
        // eps(phi_i) : T_c = sum_b sym(e_a (x) grad)_{..}: with T_c
        // having ones at (p,q) and (q,p).
        for (unsigned int j = 0; j < n_s; ++j)
          {
            const auto &pq    = pq_s[j];
            double      eps_T = 0;
            if (pq.first == pq.second)
              eps_T = (a == pq.first) ? grad[a] : 0.;
            else
              eps_T = (a == pq.first ? grad[pq.second] : 0.) +
                      (a == pq.second ? grad[pq.first] : 0.);
            if (eps_T != 0)
              (*Bc)(i, j) += eps_T * psi[j] * JxW;
          }
      }
  }

  template <int dim>
  void
  CellIntegrator<dim>::volume_terms(const cell_iterator    &cu,
                                    const MaterialLaw<dim> &material,
                                    const bool              same,
                                    const bool              strain_term)
  {
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const double JxW = fv_u.JxW(q);
        if (!(JxW > 0))
          {
            std::ostringstream s;
            s << "Geometry: the cell with centre (" << cu->center()
              << ") is inverted or too distorted (non-positive Jacobian "
                 "at a quadrature point).";
            throw InputError(s.str());
          }
        if (same)
          {
            body_force_term(q, JxW);
            continue;
          }
        if (stress_state)
          {
            sigma_q = 0;
            for (unsigned int j = 0; j < n_s; ++j)
              sigma_q += s_loc[j] * fv_s.shape_value(j, q) * T[comp_s[j]];
          }
        if (cone)
          {
            cone_term(q, JxW, cu);
            continue;
          }
        for (unsigned int c = 0; c < n_comp; ++c)
          for (unsigned int d = 0; d < n_comp; ++d)
            K(c, d) =
              T[c] * material.compliance_times(sigma_q,
                                               T[d],
                                               fv_u.quadrature_point(q));
        for (unsigned int j = 0; j < n_s; ++j)
          psi[j] = fv_s.shape_value(j, q);
        if (strain_term)
          {
            const SymmetricTensor<2, dim> eps =
              material.strain(sigma_q, fv_u.quadrature_point(q));
            for (unsigned int i = 0; i < n_s; ++i)
              (*st)(i) += psi[i] * (T[comp_s[i]] * eps) * JxW;
          }
        compliance_term(q, JxW);
        equilibrium_term(q, JxW);
        body_force_term(q, JxW);
      }
  }

  template <int dim>
  void
  CellIntegrator<dim>::cone_term(const unsigned int   q,
                                 const double         JxW,
                                 const cell_iterator &cu)
  {
    // sigma_q holds the point's strain state here.
    SymmetricTensor<4, dim> F;
    SymmetricTensor<2, dim> e;
    cone->model(cu->active_cell_index(), q, sigma_q, F, e);
    for (unsigned int c = 0; c < n_comp; ++c)
      for (unsigned int d = 0; d < n_comp; ++d)
        K(c, d) = T[c] * (F * T[d]);
    for (unsigned int j = 0; j < n_s; ++j)
      psi[j] = fv_s.shape_value(j, q);
    for (unsigned int i = 0; i < n_s; ++i)
      (*st)(i) += psi[i] * (T[comp_s[i]] * e) * JxW;
    compliance_term(q, JxW);
    equilibrium_term(q, JxW);
    body_force_term(q, JxW);
  }

  template <int dim>
  void
  CellIntegrator<dim>::constraint_term(const cell_iterator &cs)
  {
    // Nothing where X has no part in the polar cone (StressConstraint).
    const StressConstraint<dim> &constraint = constraint_field->constraint;
    const double                 alpha      = constraint_field->alpha;
    fv_vertex->reinit(typename Triangulation<dim>::cell_iterator(cs));
    for (unsigned int t = 0; t < fv_vertex->n_quadrature_points; ++t)
      {
        sigma_q = 0;
        if (stress_state)
          for (unsigned int j = 0; j < n_s; ++j)
            sigma_q += s_loc[j] * fv_vertex->shape_value(j, t) * T[comp_s[j]];
        const SymmetricTensor<2, dim> X =
          constraint_field->multiplier(blocks.cell, t) + alpha * sigma_q;
        constraint.linearise(X, T, P, DP);
        if (P.norm() == 0)
          continue;
        for (unsigned int c = 0; c < n_comp; ++c)
          for (unsigned int d = 0; d < n_comp; ++d)
            K_vertex(c, d) = alpha * (T[c] * DP[d]);
        const double JxW = fv_vertex->JxW(t);
        for (unsigned int i = 0; i < n_s; ++i)
          {
            const double psi_i = fv_vertex->shape_value(i, t);
            if (psi_i == 0)
              continue;
            (*st)(i) += psi_i * (T[comp_s[i]] * P) * JxW;
            for (unsigned int j = 0; j < n_s; ++j)
              {
                const double k = K_vertex(comp_s[i], comp_s[j]);
                if (k != 0)
                  (*Fc)(i, j) += psi_i * fv_vertex->shape_value(j, t) * k * JxW;
              }
          }
      }
  }

  template <int dim>
  void
  CellIntegrator<dim>::traction_terms(const cell_iterator &cu)
  {
    const auto &fe_u = *spaces.fe_displacement;
    for (const auto f : cu->face_indices())
      if (cu->face(f)->at_boundary())
        {
          const types::boundary_id id = cu->face(f)->boundary_id();
          const auto               t  = scene.tractions.find(id);
          const auto               pp = scene.projected_pressures.find(id);
          if (t == scene.tractions.end() &&
              pp == scene.projected_pressures.end())
            continue;
          fv_face.reinit(cu, f);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            {
              force = 0;
              if (t != scene.tractions.end())
                t->second->vector_value(fv_face.quadrature_point(q), force);
              if (pp != scene.projected_pressures.end())
                {
                  // t_k = -p_k n_k: each pressure on its projection.
                  pp->second->vector_value(fv_face.quadrature_point(q),
                                           pressure);
                  const Tensor<1, dim> n = fv_face.normal_vector(q);
                  for (unsigned int d = 0; d < dim; ++d)
                    force(d) -= pressure(d) * n[d];
                }
              for (unsigned int i = 0; i < n_u; ++i)
                {
                  const unsigned int a =
                    fe_u.system_to_component_index(i).first;
                  blocks.load(i) +=
                    fv_face.shape_value(i, q) * force(a) * fv_face.JxW(q);
                }
            }
        }
  }

  template <int dim>
  void
  CellIntegrator<dim>::check_loads(const cell_iterator &cu) const
  {
    for (unsigned int i = 0; i < n_u; ++i)
      if (!std::isfinite(blocks.load(i)))
        {
          std::ostringstream s;
          s << "Loads: the body force or a traction is not finite near ("
            << cu->center() << ").";
          throw InputError(s.str());
        }
  }

  template <int dim>
  void
  CellIntegrator<dim>::reduce_to_parameters(const bool same)
  {
    // A translated cell has the same T_c: its reduced blocks too.
    if (!same)
      {
        blocks.B.reinit(n_u, n_p);
        blocks.F.reinit(n_p, n_p);
        Bc->mmult(blocks.B, T_c);
        blocks.F.triple_product(*Fc, T_c, T_c, true, false);
      }
    blocks.strain_term.reinit(st->size() > 0 ? n_p : 0);
    if (st->size() > 0)
      T_c.Tvmult(blocks.strain_term, *st);
  }

  template <int dim>
  const CellBlocks &
  CellIntegrator<dim>::integrate(const cell_iterator &cu,
                                 const cell_iterator &cs)
  {
    blocks.cell = cu->active_cell_index();
    fv_u.reinit(cu);
    fv_s.reinit(typename Triangulation<dim>::cell_iterator(cs));
    cu->get_dof_indices(blocks.displacement_dofs);
    cs->get_dof_indices(blocks.stress_dofs);
    read_stress_state(cs);

    // A translation of the previous cell (deal.II's CellSimilarity:
    // FEValues then copies its Jacobians, so JxW and the gradients are
    // the same numbers) of a homogeneous, stress-independent material:
    // F_c and B_c are the previous cell's to the last bit; only the
    // load, which depends on the position, is integrated again. On the
    // uniform 3D block nearly every cell is one (doc/benchmarks.md).
    const MaterialLaw<dim> &material = scene.material_of(cu->material_id());
    const bool              same =
      reuse_blocks &&
      fv_u.get_cell_similarity() == CellSimilarity::translation &&
      cu->material_id() == previous_body;
    blocks.same_as_previous = same;
    reuse_blocks            = may_reuse && material.is_homogeneous();
    previous_body           = cu->material_id();
    if (!same)
      {
        *Fc = 0;
        *Bc = 0;
      }
    blocks.load = 0;
    // A nonlinear law at a stress state, or a stress constraint: e_c =
    // int psi : eps(sigma).
    const bool strain_term =
      (stress_state && !material.is_linear()) || constraint_field || cone;
    st = parameters ? &strain_values : &blocks.strain_term;
    st->reinit(strain_term ? n_s : 0);
    volume_terms(cu, material, same, strain_term);
    if (constraint_field && !same)
      constraint_term(cs);
    traction_terms(cu);
    check_loads(cu);
    // d_c = e_c - F_c s_c (CellBlocks::strain_term); the cone's e_q has it.
    if (strain_term && stress_state && !cone)
      for (unsigned int i = 0; i < n_s; ++i)
        for (unsigned int j = 0; j < n_s; ++j)
          (*st)(i) -= (*Fc)(i, j) * s_loc[j];
    if (parameters)
      reduce_to_parameters(same);
    return blocks;
  }

  template class CellIntegrator<2>;
  template class CellIntegrator<3>;
} // namespace hrcontact
