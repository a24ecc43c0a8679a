#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/material/linear_elasticity.h>
#include <hrcontact/solvers/condensed/linear_back_end.h>
#include <hrcontact/solvers/material_loop.h>

#include <algorithm>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  MaterialLoop<dim>::declare_parameters(ParameterHandler &prm)
  {
    MaterialIteration::declare_parameters(prm);
    StressConstraintIteration::declare_parameters(prm);
    BarrierPath::declare_parameters(prm);
  }

  template <int dim>
  void
  MaterialLoop<dim>::parse_parameters(ParameterHandler &prm)
  {
    material_iteration.parse_parameters(prm);
    constraint_iteration.parse_parameters(prm);
    barrier_path.parse_parameters(prm);
  }

  template <int dim>
  bool
  MaterialLoop<dim>::iterates(const Scene<dim> &scene)
  {
    return !scene.all_linear() || scene.stress_constraint != nullptr;
  }

  template <int dim>
  StressConstraintIteration::Method
  MaterialLoop<dim>::method(const Scene<dim>  &scene,
                            const std::string &stress_element) const
  {
    using Method = StressConstraintIteration::Method;
    if (constraint_iteration.method != Method::automatic)
      return constraint_iteration.method;
    // Constraint points other than the default belong to the augmented
    // Lagrangian: a file that chose them keeps it (and its results).
    const bool applies = scene.stress_constraint &&
                         scene.stress_constraint->has_closed_form() &&
                         stress_element == "DGQ1" && scene.all_linear() &&
                         constraint_iteration.constraint_points == "vertices";
    return applies ? Method::interior_point : Method::augmented_lagrangian;
  }

  template <int dim>
  bool
  MaterialLoop<dim>::projects_constraint(
    const Scene<dim>  &scene,
    const std::string &stress_element) const
  {
    return scene.stress_constraint &&
           method(scene, stress_element) !=
             StressConstraintIteration::Method::augmented_lagrangian;
  }

  template <int dim>
  void
  MaterialLoop<dim>::run(EquilibriumSystem           &system,
                         NewtonStepPath              &path,
                         const std::function<void()> &solve_once,
                         Results<dim>                &r,
                         std::ostream                &log)
  {
    r.material.newton_steps = 0;
    r.material.changes.clear();
    r.stress_constraint.residuals.clear();
    r.stress_constraint.inner_steps.clear();
    r.stress_constraint.field = nullptr;
    if (!iterates(r.scene))
      {
        solve_once();
        return;
      }
    // Newton on the complementary energy: F_c and d_c refreshed at the last
    // stresses (on a distributed mesh each process those of its own and
    // ghost cells, all the cells it assembles).
    MaterialIteration::Operations operations;
    operations.solve    = solve_once;
    operations.stresses = [&](FieldVector &s) {
      reinit_field(s, r.spaces.stress_unknowns());
      path.stresses(s);
    };
    if (r.scene.stress_constraint)
      {
        if (projects_constraint(r.scene, r.spaces.stress_element_name))
          try
            {
              run_projected(system, path, operations, r, log);
            }
          catch (const SingularStiffnessError &e)
            {
              throw InputError(cracked_region_hint(
                e.what(), r.scene, r.spaces.stress_element_name));
            }
        else
          run_constrained(system, path, operations, r, log);
        return;
      }
    HRAssembler<dim> assembler(r.scene, r.spaces);
    operations.linearise_at = [&](const FieldVector &s) {
      assembler.refresh_flexibility(system, s);
      path.flexibility_changed();
    };
    solve_material_iteration(operations, r, log);
    log << "  material iteration: " << r.material.newton_steps
        << " Newton steps" << std::endl;
  }

  template <int dim>
  void
  MaterialLoop<dim>::solve_material_iteration(
    const MaterialIteration::Operations &operations,
    Results<dim>                        &r,
    std::ostream                        &log)
  {
    material_iteration.solve(operations, log);
    r.material.newton_steps += material_iteration.n_steps();
    r.material.changes.insert(r.material.changes.end(),
                              material_iteration.change_history().begin(),
                              material_iteration.change_history().end());
  }

  template <int dim>
  void
  MaterialLoop<dim>::run_constrained(EquilibriumSystem            &system,
                                     NewtonStepPath               &path,
                                     MaterialIteration::Operations operations,
                                     Results<dim>                 &r,
                                     std::ostream                 &log)
  {
    using Points     = typename StressConstraintField<dim>::Points;
    constraint_field = std::make_unique<StressConstraintField<dim>>(
      *r.scene.stress_constraint,
      r.spaces,
      constraint_iteration.constraint_points == "vertices" ?
        Points::vertices :
      constraint_iteration.constraint_points == "Gauss points" ?
        Points::gauss_points :
        Points::cell_centres);
    HRAssembler<dim> assembler(r.scene, r.spaces);
    assembler.constraint_field = constraint_field.get();
    operations.linearise_at    = [&](const FieldVector &s) {
      assembler.refresh_flexibility(system, s);
      path.flexibility_changed();
    };
    // The semismooth constraint term can make full Newton steps cycle: an
    // exact line search on the complementary energy damps them.
    operations.energy_slope = [&](const FieldVector &s0,
                                  const FieldVector &delta,
                                  const double       theta,
                                  double            *curvature) {
      return assembler.energy_slope(s0, delta, theta, curvature);
    };
    // The stress constraint's augmented Lagrangian around it, the inner
    // tolerance following the residual (Step 2), never below the material
    // iteration's own.
    const double material_tolerance = material_iteration.relative_tolerance;
    StressConstraintIteration::Operations c;
    c.solve_material = [&](const double eps) {
      material_iteration.relative_tolerance = std::max(eps, material_tolerance);
      solve_material_iteration(operations, r, log);
      material_iteration.relative_tolerance = material_tolerance;
      const auto &changes = material_iteration.change_history();
      // A stop at the path's round-off floor counts as converged.
      return std::make_pair(material_iteration.n_steps(),
                            (changes.empty() ||
                             material_iteration.stopped_at_roundoff()) ?
                              0. :
                              changes.back());
    };
    c.stresses           = operations.stresses;
    c.update_multipliers = [&](const FieldVector &s) {
      return constraint_field->update_multipliers(s);
    };
    c.set_penalty = [&](const double alpha) {
      constraint_field->alpha = alpha;
    };
    c.violation = [&](const FieldVector &s) {
      return constraint_field->largest_violation(s);
    };
    c.linearise_at                       = operations.linearise_at;
    const LinearElasticity<dim> *elastic = r.scene.material->elastic_part();
    log << "  stress constraint '" << r.scene.stress_constraint->name()
        << "' at " << constraint_field->quadrature().size()
        << " point(s) per cell (" << constraint_iteration.constraint_points
        << "), consistent augmented Lagrangian" << std::endl;
    constraint_iteration.solve(c,
                               elastic ? 1. / elastic->youngs_modulus() : 1.,
                               log);
    r.stress_constraint.residuals   = constraint_iteration.residual_history();
    r.stress_constraint.inner_steps = constraint_iteration.inner_step_history();
    r.stress_constraint.cracked_fraction = constraint_field->cracked_fraction();
    r.stress_constraint.largest_fracture_strain =
      constraint_field->largest_opening();
    r.stress_constraint.field = constraint_field.get();
    log << "  stress constraint: " << r.stress_constraint.residuals.size()
        << " multiplier updates, " << r.material.newton_steps
        << " material Newton steps, cracked fraction "
        << r.stress_constraint.cracked_fraction << std::endl;
  }

  template <int dim>
  void
  MaterialLoop<dim>::run_projected(EquilibriumSystem            &system,
                                   NewtonStepPath               &path,
                                   MaterialIteration::Operations operations,
                                   Results<dim>                 &r,
                                   std::ostream                 &log)
  {
    const bool interior = method(r.scene, r.spaces.stress_element_name) ==
                          StressConstraintIteration::Method::interior_point;
    r.stress_constraint.gauss_point_method =
      interior ? "interior point" : "closed-form projection";
    cone = std::make_unique<GaussPointCone<dim>>(
      *r.scene.stress_constraint,
      r.scene,
      r.spaces,
      interior ? barrier_path.residual_stiffness :
                 constraint_iteration.residual_stiffness);
    HRAssembler<dim> assembler(r.scene, r.spaces);
    assembler.cone = cone.get();
    // The state: the point strains of the last step (zero: the first step
    // is the elastic solve; or a coarser level's answer, prolongated).
    FieldVector state, stress;
    reinit_field(state, r.spaces.stress_unknowns());
    const FieldVector &start   = r.stress_constraint.start_point_strains;
    const bool         carried = start.size() == state.size();
    if (carried)
      state.copy_locally_owned_data_from(start);
    state.update_ghost_values();
    // The first step's largest stress and strain (a carried level's first
    // step judged against the coarser stress scale: run_barrier_path).
    double elastic_stress =
      carried && interior ? r.stress_constraint.elastic_stress : 0;
    double first_stress = 0, elastic_strain = 0, model_error = 0, growth = 0;
    // Converged when the model's stresses are the law's (the strains of
    // cracked regions need not settle: they are not unique).
    operations.change = [&](const FieldVector &, const FieldVector &) {
      return model_error;
    };
    operations.linearise_at = [&](const FieldVector &eps) {
      state.copy_locally_owned_data_from(eps);
      state.update_ghost_values();
      cone->linearise(state);
      assembler.refresh_flexibility(system, state);
      path.flexibility_changed();
    };
    operations.stresses = [&](FieldVector &eps) {
      step_strains(path, state, r, stress, eps);
      // Relative to the largest stress of this solve or of the elastic one
      // (a homogeneous tension ends with no stress at all).
      const auto [error, scale] = cone->model_error(stress, eps);
      if (first_stress == 0)
        first_stress = scale;
      if (elastic_stress == 0)
        elastic_stress = scale;
      const double reference = std::max(scale, elastic_stress);
      model_error            = reference > 0 ? error / reference : error;
      // A load only tension could carry has no minimiser: the cracks open
      // a mechanism and the strains grow without bound.
      const double largest = cone->largest_strain(eps);
      if (elastic_strain == 0)
        elastic_strain = largest;
      else
        growth = std::max(growth, largest / elastic_strain);
      // The barrier's cracked strips legitimately open to about 1 /
      // allowance (run_barrier_path): there only round-off limits them.
      if (growth > (interior ? 1e8 : 1e4))
        throw no_admissible_field(
          r.scene,
          growth,
          "material step " + std::to_string(material_iteration.n_steps()));
    };
    operations.energy_slope = [&](const FieldVector &eps0,
                                  const FieldVector &delta,
                                  const double       theta,
                                  double            *curvature) {
      return cone->slope(eps0, delta, theta, curvature);
    };
    log << "  stress constraint '" << r.scene.stress_constraint->name()
        << "' in closed form at the " << (1 << dim)
        << " Gauss points of each cell (Newton on the point strains)"
        << std::endl;
    operations.linearise_at(state);
    const double material_tolerance = material_iteration.relative_tolerance;
    material_iteration.state_name   = "model stress";
    // Stress tolerance = automatic: 1e-4 gives the interior point's
    // stresses of 1e-6 to about six digits (doc/materials.md).
    const double stress_tolerance = constraint_iteration.stress_tolerance > 0 ?
                                      constraint_iteration.stress_tolerance :
                                      (interior ? 1e-4 : 1e-6);
    material_iteration.relative_tolerance = stress_tolerance;
    if (interior)
      run_barrier_path(operations,
                       state,
                       elastic_stress,
                       first_stress,
                       growth,
                       stress_tolerance,
                       carried,
                       r,
                       log);
    else
      solve_material_iteration(operations, r, log);
    r.stress_constraint.elastic_stress    = elastic_stress;
    material_iteration.state_name         = "stress";
    material_iteration.relative_tolerance = material_tolerance;
    FieldVector &last                     = r.stress_constraint.point_strains;
    operations.stresses(last);
    store_fracture_strains(last, r, log);
  }

  template <int dim>
  void
  MaterialLoop<dim>::store_fracture_strains(const FieldVector &strains,
                                            Results<dim>      &r,
                                            std::ostream      &log)
  {
    constraint_field = std::make_unique<StressConstraintField<dim>>(
      *r.scene.stress_constraint,
      r.spaces,
      StressConstraintField<dim>::Points::gauss_points);
    cone->store_fracture_strains(strains, *constraint_field);
    r.stress_constraint.cracked_fraction = constraint_field->cracked_fraction();
    r.stress_constraint.largest_fracture_strain =
      constraint_field->largest_opening();
    r.stress_constraint.field = constraint_field.get();
    log << "  stress constraint: " << r.material.newton_steps
        << " material Newton steps, cracked fraction "
        << r.stress_constraint.cracked_fraction << std::endl;
  }

  template <int dim>
  void
  MaterialLoop<dim>::step_strains(const NewtonStepPath &path,
                                  const FieldVector    &state,
                                  const Results<dim>   &r,
                                  FieldVector          &stress,
                                  FieldVector          &strain) const
  {
    if (path.displacements_are_unknowns())
      {
        FieldVector u;
        reinit_field(u, r.spaces.dof_handler_displacement);
        path.displacements({}, u);
        cone->strains_and_stresses(u, state, strain, stress);
        return;
      }
    reinit_field(stress, r.spaces.stress_unknowns());
    path.stresses(stress);
    cone->strains_of_solve(state, stress, strain);
  }

  template <int dim>
  std::string
  MaterialLoop<dim>::cracked_region_hint(
    const std::string &singular,
    const Scene<dim>  &scene,
    const std::string &stress_element) const
  {
    const bool interior = method(scene, stress_element) ==
                          StressConstraintIteration::Method::interior_point;
    std::ostringstream s;
    s << singular << " With Material/Admissible stresses = "
      << scene.stress_constraint->name()
      << ", a region cracked in every direction has no stiffness of its own: "
         "its Newton systems are held only by Stress constraint iteration/"
      << (interior ? "Barrier residual stiffness" : "Residual stiffness")
      << " (" << cone->residual_stiffness << " of C here, "
      << (interior ? BarrierPath().residual_stiffness :
                     StressConstraintIteration().residual_stiffness)
      << " by default); raise it if it is below that.";
    return s.str();
  }

  template <int dim>
  NotConvergedError
  MaterialLoop<dim>::no_admissible_field(const Scene<dim>  &scene,
                                         const double       growth,
                                         const std::string &when)
  {
    return NotConvergedError(
      "Material/Admissible stresses = " + scene.stress_constraint->name() +
      ": no admissible stress field carries this load (the strains grew to " +
      std::to_string(growth) +
      " times the elastic ones as the cracks opened a mechanism, " + when +
      ").");
  }

  template <int dim>
  void
  MaterialLoop<dim>::run_barrier_path(
    const MaterialIteration::Operations &operations,
    FieldVector                         &state,
    double                              &elastic_stress,
    const double                        &first_stress,
    double                              &growth,
    const double                         stress_tolerance,
    const bool                           carried,
    Results<dim>                        &r,
    std::ostream                        &log)
  {
    // The elastic step (zero strain, no barrier: the elastic tangent) sets
    // the barrier's scale s^2 / E. On a carried level it is one step of the
    // closed-form projection from the coarser answer, its model stress error
    // measured against the coarser level's scale: where the crack pattern
    // stays it lands near the finer answer (the manufactured pier: 2 at 32
    // across), where the cracks moved far off it (the arch's hinges: 2e5);
    // such a start is rejected, its contact solve taken back, and the level
    // follows the path from the coarser level's strains at Carried initial
    // barrier instead of the last stage alone (4,096 arch cells: 28 steps
    // instead of 47).
    FieldVector last;
    operations.solve();
    r.material.newton_steps += 1;
    operations.stresses(last);
    const FieldVector &path_start  = r.stress_constraint.start_path_strains;
    const double       first_error = operations.change(last, last);
    const bool         restarts =
      carried && path_start.size() == state.size() && first_error > 1e2;
    if (restarts)
      {
        // The path's barrier keeps the coarser level's units (its strains
        // at Carried initial barrier are on that path); not its strain
        // scale: the growth test compares strains on one mesh (a
        // concentrated load's elastic peak grows as the mesh is refined).
        growth                                     = 0;
        r.stress_constraint.carried_start_rejected = true;
        log << "  the carried start is far off (model stress error "
            << first_error << "): the path from Carried initial barrier"
            << std::endl;
        if (take_back_last_solve)
          take_back_last_solve();
        copy_field(path_start, last);
      }
    else
      // The level's own scale, as from the elastic step (the manufactured
      // pier at 790k dofs: 6 steps on the finest level, 8 with the coarser
      // scale).
      elastic_stress = first_stress;
    const LinearElasticity<dim> *elastic = r.scene.material->elastic_part();
    const double                 unit    = elastic_stress * elastic_stress /
                        (elastic ? elastic->youngs_modulus() : 1.);
    MaterialIteration::Operations staged = operations;
    staged.start                         = &state;
    staged.stresses                      = [&](FieldVector &eps) {
      operations.stresses(eps);
      copy_field(eps, last);
    };
    // The strains where the path passes Carried initial barrier go to the
    // next level (NestedLevelRunner) with the answer, for a start over.
    const double first_barrier = !carried ? barrier_path.initial_barrier :
                                 restarts ? barrier_path.carried_barrier :
                                            barrier_path.final_barrier;
    const bool   passes =
      first_barrier >= barrier_path.carried_barrier * (1 - 1e-12);
    double       stage_barrier = 0;
    FieldVector &snapshot      = r.stress_constraint.carried_point_strains;
    snapshot.reinit(0);
    const auto set_barrier = [&](const double t) {
      stage_barrier   = t;
      cone->barrier   = t * unit;
      cone->allowance = barrier_path.allowance * elastic_stress;
      operations.linearise_at(last);
    };
    const auto solve_stage = [&](const double tolerance) {
      material_iteration.relative_tolerance = tolerance;
      try
        {
          solve_material_iteration(staged, r, log);
        }
      catch (const NotConvergedError &e)
        {
          // A load only tension could carry has no minimiser at any
          // barrier: the strains grow until a solve (the contact
          // iteration, the Newton steps) gives up. Cracked strips of
          // admissible loads open to 1e4-1e5 times the elastic strains
          // (the point-load pier: 9e4), mechanisms beyond 1e5 (the arch
          // below its minimum thickness: 8e5 when its contact gives up).
          if (growth <= 1e5)
            throw;
          throw no_admissible_field(r.scene,
                                    growth,
                                    std::string("then: ") + e.what());
        }
      if (passes && snapshot.size() == 0 &&
          stage_barrier <= barrier_path.carried_barrier * (1 + 1e-12))
        copy_field(last, snapshot);
      return material_iteration.n_steps();
    };
    barrier_path.run(
      set_barrier, solve_stage, stress_tolerance, first_barrier, log);
    // A level that passed no stage at Carried initial barrier hands on the
    // coarser level's point of it.
    if (snapshot.size() == 0 && path_start.size() == state.size())
      copy_field(path_start, snapshot);
  }

  template class MaterialLoop<2>;
  template class MaterialLoop<3>;
} // namespace hrcontact
