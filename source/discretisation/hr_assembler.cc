#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/constraints/constraint_source.h>
#include <hrcontact/discretisation/cell_integrator.h>
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
    CellIntegrator<dim> integrator(
      scene, spaces, stress_state.get(), constraint_field, cone);
    auto cs = spaces.stress_unknowns().begin_active();
    for (const auto &cu :
         spaces.dof_handler_displacement.active_cell_iterators())
      {
        // A distributed mesh: only this process's and its ghost cells.
        if (!cu->is_artificial() && filter(cu->active_cell_index()))
          worker(integrator.integrate(cu, cs));
        ++cs;
      }
  }

  namespace
  {
    /** The cells touching the node of a Q or H row (a lean system stores
     * only their blocks). */
    template <int dim>
    void
    mark_stored_cells(EquilibriumSystem &system, const DoFHandler<dim> &dh_u)
    {
      std::vector<bool> constrained(dh_u.n_dofs(), false);
      // A row's hanging shares read the cells around those hanging nodes.
      for (const auto &row : system.rows)
        if (row.row_class != RowClass::free)
          for (const auto *terms : {&row.combination, &row.shares})
            for (const auto &[dof, c] : *terms)
              constrained[dof] = true;
      system.stored_cell.assign(dh_u.get_triangulation().n_active_cells(),
                                false);
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

    /** B's sparsity from the stored cells' dofs (rows b_row(dof)). */
    template <int dim>
    void
    build_b_sparsity(EquilibriumSystem &system, const MixedSpaces<dim> &spaces)
    {
      const DoFHandler<dim> &dh_u = spaces.dof_handler_displacement;
      DynamicSparsityPattern dsp(system.B_dofs.size() == 0 ?
                                   dh_u.n_dofs() :
                                   system.B_dofs.n_elements(),
                                 system.n_stress_dofs);
      std::vector<types::global_dof_index> du, ds;
      auto cs = spaces.stress_unknowns().begin_active();
      for (const auto &cu : dh_u.active_cell_iterators())
        {
          if (!cu->is_artificial() && system.is_stored(cu->active_cell_index()))
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
  } // namespace

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
      mark_stored_cells(system, dh_u);
    auto stored = [&](const unsigned int c) { return system.is_stored(c); };
    auto owned  = [&](const unsigned int c) {
      return !lean || lean->owned_cell[c];
    };

    // B's rows: every dof, or on a distributed mesh the owned and ghost ones.
    system.B_dofs = IndexSet();
    if (lean && lean->distributed_mesh)
      system.B_dofs = lean->relevant;
    build_b_sparsity(system, spaces);
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
          sum_over_processes(system.load, lean->communicator);
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
      [&scene_,
       &spaces_,
       state = stress_state,
       field = constraint_field,
       cone  = cone](const std::function<bool(unsigned int)>       &filter,
                    const std::function<void(const CellBlocks &)> &worker) {
        HRAssembler<dim> assembler(scene_, spaces_);
        assembler.stress_state     = state;
        assembler.constraint_field = field;
        assembler.cone             = cone;
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
    if (!scene.all_linear() || constraint_field || cone)
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
