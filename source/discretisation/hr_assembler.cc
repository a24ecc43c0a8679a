#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/constraints/constraint_source.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/discretisation/row_classification.h>
#include <hrcontact/discretisation/stress_constraint_field.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  HRAssembler<dim>::HRAssembler(const Scene<dim>       &scene,
                                const MixedSpaces<dim> &spaces)
    : scene(scene)
    , spaces(spaces)
  {}

  template <int dim>
  void
  HRAssembler<dim>::for_each_cell(
    const std::function<bool(unsigned int)>       &filter,
    const std::function<void(const CellBlocks &)> &worker) const
  {
    const DoFHandler<dim> &dh_u   = spaces.dof_handler_displacement;
    const DoFHandler<dim> &dh_s   = spaces.stress_unknowns();
    const auto            &fe_u   = *spaces.fe_displacement;
    const auto            &fe_s   = *spaces.fe_stress;
    constexpr unsigned int n_comp = MixedSpaces<dim>::n_stress_components;
    // An assumed-stress element: the blocks are integrated in the value
    // element and handed on as B_c T_c, T_c^T F_c T_c, T_c^T d_c.
    const bool         parameters = spaces.has_parameters();
    const unsigned int n_p        = dh_s.get_fe().n_dofs_per_cell();

    // Q1 x DGQ1 products are integrated exactly on parallelograms by 2 Gauss
    // points per direction; so are the constant-stress patch tests on
    // general quadrilaterals and hexahedra (cof(J) grad phi is polynomial).
    const QGauss<dim>     quadrature(2);
    const QGauss<dim - 1> face_quadrature(2);
    FEValues<dim>         fv_u(fe_u,
                       quadrature,
                       update_gradients | update_values |
                         update_quadrature_points | update_JxW_values);
    FEValues<dim>         fv_s(fe_s, quadrature, update_values);
    FEFaceValues<dim>     fv_face(fe_u,
                              face_quadrature,
                              update_values | update_quadrature_points |
                                update_normal_vectors | update_JxW_values);

    const unsigned int n_u = fe_u.n_dofs_per_cell();
    const unsigned int n_s = fe_s.n_dofs_per_cell();

    // The compliance in the stress basis at each quadrature point:
    // K(c, c') = T_c : C(sigma) T_c', C the material's d^2 phi^c / d sigma^2
    // at the stress state of the point (zero before a solve).
    FullMatrix<double>                   K(n_comp, n_comp);
    std::vector<SymmetricTensor<2, dim>> T(n_comp);
    for (unsigned int c = 0; c < n_comp; ++c)
      T[c] = MixedSpaces<dim>::stress_basis_tensor(c);
    SymmetricTensor<2, dim> sigma_q;
    // The component of each shape function and, per stress shape function,
    // the index pair of its basis tensor: looked up once, not in the n_s^2
    // and n_u n_s loops below (same sums in the same order).
    std::vector<unsigned int>                          comp_u(n_u), comp_s(n_s);
    std::vector<std::pair<unsigned int, unsigned int>> pq_s(n_s);
    for (unsigned int i = 0; i < n_u; ++i)
      comp_u[i] = fe_u.system_to_component_index(i).first;
    for (unsigned int j = 0; j < n_s; ++j)
      {
        comp_s[j] = fe_s.system_to_component_index(j).first;
        pq_s[j]   = MixedSpaces<dim>::stress_component_indices(comp_s[j]);
      }
    std::vector<double> psi(n_s);

    CellBlocks blocks;
    auto      &du = blocks.displacement_dofs;
    auto      &ds = blocks.stress_dofs;
    // In the value element: the blocks themselves, or scratch to reduce.
    FullMatrix<double> F_values, B_values, T_c;
    Vector<double>     strain_values, s_loc(n_s), beta(n_p);
    auto              &Fc = parameters ? F_values : blocks.F;
    auto              &Bc = parameters ? B_values : blocks.B;
    auto              &fc = blocks.load;
    du.resize(n_u);
    ds.resize(n_p);
    Bc.reinit(n_u, n_s);
    Fc.reinit(n_s, n_s);
    fc.reinit(n_u);
    Vector<double> force(dim), pressure(dim);
    auto add_body_force = [&](const unsigned int q, const double JxW) {
      if (!scene.body_force)
        return;
      scene.body_force->vector_value(fv_u.quadrature_point(q), force);
      for (unsigned int i = 0; i < n_u; ++i)
        fc(i) += fv_u.shape_value(i, q) * force(comp_u[i]) * JxW;
    };
    // Only after a first cell, and only where F_c does not depend on the
    // position or the stresses.
    bool       reuse_blocks = false;
    const bool may_reuse    = !stress_state && !constraint_field;
    // Each body its own law (Bodies): the cell's material id is its body.
    types::material_id previous_body = numbers::invalid_material_id;
    // A stress constraint's term at its points (StressConstraintField).
    std::unique_ptr<FEValues<dim>>       fv_vertex;
    FullMatrix<double>                   K_vertex(n_comp, n_comp);
    SymmetricTensor<2, dim>              P;
    std::vector<SymmetricTensor<2, dim>> DP;
    if (constraint_field)
      fv_vertex =
        std::make_unique<FEValues<dim>>(fe_s,
                                        constraint_field->quadrature(),
                                        update_values | update_JxW_values);
    auto cs = dh_s.begin_active();
    for (const auto &cu : dh_u.active_cell_iterators())
      {
        blocks.cell = cu->active_cell_index();
        // A distributed mesh: only this process's and its ghost cells.
        if (cu->is_artificial() || !filter(blocks.cell))
          {
            ++cs;
            continue;
          }
        fv_u.reinit(cu);
        fv_s.reinit(typename Triangulation<dim>::cell_iterator(cs));
        cu->get_dof_indices(du);
        cs->get_dof_indices(ds);
        // The stress state's value dofs on this cell.
        if (parameters)
          spaces.cell_expansion(cs, T_c);
        if (stress_state)
          {
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
            Fc = 0;
            Bc = 0;
          }
        fc = 0;
        // A nonlinear law at a stress state, or a stress constraint: e_c =
        // int psi : eps(sigma).
        const bool strain_term =
          (stress_state && !material.is_linear()) || constraint_field;
        auto &st = parameters ? strain_values : blocks.strain_term;
        st.reinit(strain_term ? n_s : 0);
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
                add_body_force(q, JxW);
                continue;
              }
            if (stress_state)
              {
                sigma_q = 0;
                for (unsigned int j = 0; j < n_s; ++j)
                  sigma_q += s_loc[j] * fv_s.shape_value(j, q) * T[comp_s[j]];
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
                  st(i) += psi[i] * (T[comp_s[i]] * eps) * JxW;
              }
            // Terms with a zero compliance or strain factor add nothing.
            for (unsigned int i = 0; i < n_s; ++i)
              {
                const unsigned int ci    = comp_s[i];
                const double       psi_i = psi[i];
                for (unsigned int j = 0; j < n_s; ++j)
                  {
                    const double k = K(ci, comp_s[j]);
                    if (k != 0)
                      Fc(i, j) += psi_i * psi[j] * k * JxW;
                  }
              }
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
                      Bc(i, j) += eps_T * psi[j] * JxW;
                  }
              }
            add_body_force(q, JxW);
          }

        // The stress constraint's augmented Lagrangian term at its points:
        // strain P(X) and compliance alpha DP(X), X = mu + alpha sigma
        // (StressConstraint); nothing where X has no part in the polar cone.
        if (constraint_field && !same)
          {
            const StressConstraint<dim> &constraint =
              constraint_field->constraint;
            const double alpha = constraint_field->alpha;
            fv_vertex->reinit(typename Triangulation<dim>::cell_iterator(cs));
            for (unsigned int t = 0; t < fv_vertex->n_quadrature_points; ++t)
              {
                sigma_q = 0;
                if (stress_state)
                  for (unsigned int j = 0; j < n_s; ++j)
                    sigma_q +=
                      s_loc[j] * fv_vertex->shape_value(j, t) * T[comp_s[j]];
                const SymmetricTensor<2, dim> X =
                  constraint_field->multiplier(blocks.cell, t) +
                  alpha * sigma_q;
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
                    st(i) += psi_i * (T[comp_s[i]] * P) * JxW;
                    for (unsigned int j = 0; j < n_s; ++j)
                      {
                        const double k = K_vertex(comp_s[i], comp_s[j]);
                        if (k != 0)
                          Fc(i, j) +=
                            psi_i * fv_vertex->shape_value(j, t) * k * JxW;
                      }
                  }
              }
          }

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
                      fc(i) +=
                        fv_face.shape_value(i, q) * force(a) * fv_face.JxW(q);
                    }
                }
            }

        for (unsigned int i = 0; i < n_u; ++i)
          {
            if (!std::isfinite(fc(i)))
              {
                std::ostringstream s;
                s << "Loads: the body force or a traction is not finite near ("
                  << cu->center() << ").";
                throw InputError(s.str());
              }
          }
        // d_c = e_c - F_c s_c (CellBlocks::strain_term).
        if (strain_term && stress_state)
          for (unsigned int i = 0; i < n_s; ++i)
            for (unsigned int j = 0; j < n_s; ++j)
              st(i) -= Fc(i, j) * s_loc[j];
        if (parameters)
          {
            // A translated cell has the same T_c: its reduced blocks too.
            if (!same)
              {
                blocks.B.reinit(n_u, n_p);
                blocks.F.reinit(n_p, n_p);
                Bc.mmult(blocks.B, T_c);
                blocks.F.triple_product(Fc, T_c, T_c, true, false);
              }
            blocks.strain_term.reinit(st.size() > 0 ? n_p : 0);
            if (st.size() > 0)
              T_c.Tvmult(blocks.strain_term, st);
          }
        worker(blocks);
        ++cs;
      }
  }

  template <int dim>
  void
  HRAssembler<dim>::assemble_blocks(EquilibriumSystem  &system,
                                    const DofPartition *lean) const
  {
    const DoFHandler<dim> &dh_u    = spaces.dof_handler_displacement;
    const unsigned int     n_cells = dh_u.get_triangulation().n_active_cells();
    system.dim                     = dim;
    system.n_displacement_dofs     = dh_u.n_dofs();
    system.n_stress_dofs           = spaces.stress_unknowns().n_dofs();

    // The stored cells: all, or those touching a Q or H row's node.
    system.stored_cell.clear();
    if (lean)
      {
        std::vector<bool> constrained(dh_u.n_dofs(), false);
        for (const auto &row : system.rows)
          if (row.row_class != RowClass::free)
            for (const auto &[dof, c] : row.combination)
              constrained[dof] = true;
        system.stored_cell.assign(n_cells, false);
        std::vector<types::global_dof_index> du;
        for (const auto &cu : dh_u.active_cell_iterators())
          if (!cu->is_artificial())
            {
              du.resize(cu->get_fe().n_dofs_per_cell());
              cu->get_dof_indices(du);
              for (const auto i : du)
                if (constrained[i])
                  system.stored_cell[cu->active_cell_index()] = true;
            }
      }
    auto stored = [&](const unsigned int c) { return system.is_stored(c); };
    auto owned  = [&](const unsigned int c) {
      return !lean || lean->owned_cell[c];
    };

    // B's rows: every dof, or on a distributed mesh the owned and ghost ones.
    system.B_dofs = IndexSet();
    if (lean && lean->distributed_mesh)
      system.B_dofs = lean->relevant;
    {
      DynamicSparsityPattern dsp(system.B_dofs.size() == 0 ?
                                   dh_u.n_dofs() :
                                   system.B_dofs.n_elements(),
                                 system.n_stress_dofs);
      std::vector<types::global_dof_index> du, ds;
      auto cs = spaces.stress_unknowns().begin_active();
      for (const auto &cu : dh_u.active_cell_iterators())
        {
          if (!cu->is_artificial() && stored(cu->active_cell_index()))
            {
              du.resize(cu->get_fe().n_dofs_per_cell());
              ds.resize(cs->get_fe().n_dofs_per_cell());
              cu->get_dof_indices(du);
              cs->get_dof_indices(ds);
              for (const auto i : du)
                for (const auto j : ds)
                  dsp.add(system.b_row(i), j);
            }
          ++cs;
        }
      system.sparsity.copy_from(dsp);
    }
    system.B.reinit(system.sparsity);
    // f: on a distributed mesh the owned and ghost dofs of this process,
    // else complete (summed over the processes below).
    const bool distributed_load = lean && lean->distributed_mesh;
    if (distributed_load)
      system.load.reinit(lean->owned, lean->relevant, lean->communicator);
    else
      system.load.reinit(dh_u.n_dofs());
    system.cell_stress_dofs.assign(n_cells, {});
    system.cell_displacement_dofs.assign(n_cells, {});
    system.cell_flexibility.assign(n_cells, FullMatrix<double>());

    // A process checks only the cells it evaluates: an error found there
    // must stop every process before the load is summed.
    std::string error;
    try
      {
        for_each_cell(
          [&](const unsigned int c) { return owned(c) || stored(c); },
          [&](const CellBlocks &b) {
            const auto &du = b.displacement_dofs;
            const auto &ds = b.stress_dofs;
            if (owned(b.cell))
              for (unsigned int i = 0; i < du.size(); ++i)
                system.load(du[i]) += b.load(i);
            if (!stored(b.cell))
              return;
            for (unsigned int i = 0; i < du.size(); ++i)
              for (unsigned int j = 0; j < ds.size(); ++j)
                if (b.B(i, j) != 0)
                  system.B.add(system.b_row(du[i]), ds[j], b.B(i, j));
            system.cell_stress_dofs[b.cell]       = ds;
            system.cell_displacement_dofs[b.cell] = du;
            system.cell_flexibility[b.cell]       = b.F;
          });
      }
    catch (const InputError &e)
      {
        error = e.what();
      }
    if (lean && lean->distributed())
      {
        for (const auto &e :
             Utilities::MPI::all_gather(lean->communicator, error))
          if (error.empty())
            error = e;
        if (error.empty() && distributed_load)
          {
            system.load.compress(VectorOperation::add);
            system.load.update_ghost_values();
          }
        else if (error.empty())
          {
            const ArrayView<const double> values(system.load.begin(),
                                                 system.load.size());
            const ArrayView<double>       sums(system.load.begin(),
                                         system.load.size());
            Utilities::MPI::sum(values, lean->communicator, sums);
          }
      }
    if (!error.empty())
      throw InputError(error);

    if (lean)
      set_recompute(system);
    else
      {
        system.recompute_cell_blocks = nullptr;
        system.recompute_cell_dofs   = nullptr;
      }
  }

  template <int dim>
  void
  HRAssembler<dim>::set_recompute(EquilibriumSystem &system) const
  {
    const Scene<dim>       &scene_  = scene;
    const MixedSpaces<dim> &spaces_ = spaces;
    system.recompute_cell_blocks =
      [&scene_, &spaces_, state = stress_state, field = constraint_field](
        const std::function<bool(unsigned int)>       &filter,
        const std::function<void(const CellBlocks &)> &worker) {
        HRAssembler<dim> assembler(scene_, spaces_);
        assembler.stress_state     = state;
        assembler.constraint_field = field;
        assembler.for_each_cell(filter, worker);
      };
    const DoFHandler<dim> &dh_u = spaces.dof_handler_displacement;
    system.recompute_cell_dofs =
      [&dh_u](const std::function<bool(unsigned int)> &filter,
              const std::function<void(
                unsigned int, const std::vector<types::global_dof_index> &)>
                &worker) {
        std::vector<types::global_dof_index> du(
          dh_u.get_fe().n_dofs_per_cell());
        for (const auto &cell : dh_u.active_cell_iterators())
          if (!cell->is_artificial() && filter(cell->active_cell_index()))
            {
              cell->get_dof_indices(du);
              worker(cell->active_cell_index(), du);
            }
      };
  }

  template <int dim>
  void
  HRAssembler<dim>::refresh_flexibility(EquilibriumSystem    &system,
                                        const Vector<double> &stress)
  {
    FieldVector complete(stress.size());
    std::copy(stress.begin(), stress.end(), complete.begin());
    refresh_flexibility(system, complete);
  }

  template <int dim>
  void
  HRAssembler<dim>::refresh_flexibility(EquilibriumSystem &system,
                                        const FieldVector &stress)
  {
    auto state = std::make_shared<FieldVector>();
    state->reinit(stress, true);
    state->copy_locally_owned_data_from(stress);
    if (!is_complete(stress))
      state->update_ghost_values();
    stress_state = state;
    system.cell_strain_term.clear();
    if (!scene.all_linear() || constraint_field)
      system.cell_strain_term.resize(system.n_cells());
    for_each_cell([&](const unsigned int c) { return system.is_stored(c); },
                  [&](const CellBlocks &b) {
                    system.cell_flexibility[b.cell] = b.F;
                    if (b.strain_term.size() > 0)
                      system.cell_strain_term[b.cell] = b.strain_term;
                  });
    if (system.recompute_cell_blocks)
      set_recompute(system);
  }

  template <int dim>
  double
  HRAssembler<dim>::energy_slope(const FieldVector &s0,
                                 const FieldVector &delta,
                                 const double       theta,
                                 double            *curvature) const
  {
    const auto            &fe_s   = *spaces.fe_stress;
    constexpr unsigned int n_comp = MixedSpaces<dim>::n_stress_components;
    const QGauss<dim>      quadrature(2);
    FEValues<dim>          fv(fe_s,
                     quadrature,
                     update_values | update_quadrature_points |
                       update_JxW_values);
    std::unique_ptr<FEValues<dim>> fv_vertex;
    if (constraint_field)
      fv_vertex =
        std::make_unique<FEValues<dim>>(fe_s,
                                        constraint_field->quadrature(),
                                        update_values | update_JxW_values);
    const unsigned int                   n_s = fe_s.n_dofs_per_cell();
    Vector<double>                       v0, vdelta;
    std::vector<SymmetricTensor<2, dim>> T(n_comp);
    for (unsigned int c = 0; c < n_comp; ++c)
      T[c] = MixedSpaces<dim>::stress_basis_tensor(c);
    std::vector<unsigned int> comp(n_s);
    for (unsigned int j = 0; j < n_s; ++j)
      comp[j] = fe_s.system_to_component_index(j).first;
    // sigma(theta) and delta sigma at point q of the values in `v`.
    const auto at = [&](const FEValues<dim> &v, const unsigned int q) {
      SymmetricTensor<2, dim> base, step;
      for (unsigned int j = 0; j < n_s; ++j)
        {
          const double psi = v.shape_value(j, q);
          if (psi == 0)
            continue;
          base += v0[j] * psi * T[comp[j]];
          step += vdelta[j] * psi * T[comp[j]];
        }
      return std::make_pair(base, step);
    };
    double slope = 0, second = 0;
    for (const auto &cell : spaces.dof_handler_stress.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const MaterialLaw<dim> &material =
          scene.material_of(cell->material_id());
        spaces.cell_values(cell, s0, v0);
        spaces.cell_values(cell, delta, vdelta);
        fv.reinit(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const auto [sigma0, dsigma] = at(fv, q);
            const Point<dim> &x         = fv.quadrature_point(q);
            slope += (material.strain(sigma0 + theta * dsigma, x) * dsigma) *
                     fv.JxW(q);
            if (curvature)
              second +=
                (material.compliance_times(sigma0, dsigma, x) * dsigma) *
                fv.JxW(q);
          }
        if (!constraint_field)
          continue;
        const StressConstraint<dim> &constraint = constraint_field->constraint;
        const double                 alpha      = constraint_field->alpha;
        fv_vertex->reinit(cell);
        for (unsigned int t = 0; t < fv_vertex->n_quadrature_points; ++t)
          {
            const auto [sigma0, dsigma] = at(*fv_vertex, t);
            const SymmetricTensor<2, dim> &mu =
              constraint_field->multiplier(cell->active_cell_index(), t);
            slope +=
              (constraint.project(mu + alpha * (sigma0 + theta * dsigma)) *
               dsigma) *
              fv_vertex->JxW(t);
            if (curvature)
              second +=
                alpha *
                (constraint.project_derivative(mu + alpha * sigma0, dsigma) *
                 dsigma) *
                fv_vertex->JxW(t);
          }
      }
    const MPI_Comm comm =
      spaces.dof_handler_stress.get_triangulation().get_communicator();
    if (curvature)
      *curvature = Utilities::MPI::sum(second, comm);
    return Utilities::MPI::sum(slope, comm);
  }

  template <int dim>
  void
  HRAssembler<dim>::classify_rows(EquilibriumSystem &system,
                                  const bool         lean_rows) const
  {
    RowClassification<dim>(scene, spaces).classify(system, lean_rows);
  }

  template class HRAssembler<2>;
  template class HRAssembler<3>;
} // namespace hrcontact
