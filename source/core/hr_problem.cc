#include <hrcontact/core/hr_problem.h>
#include <hrcontact/core/run.h>
#include <hrcontact/core/run_summary.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/solvers/condensed/condensed_step.h>
#include <hrcontact/solvers/contact_solve.h>
#include <hrcontact/solvers/field_recovery.h>
#include <hrcontact/solvers/null_space_step.h>

#include <filesystem>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  HRProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    Scene<dim>::declare_parameters(prm);
    MixedSpaces<dim>::declare_parameters(prm);
    PathChoice::declare_parameters(prm);
    EquilibriumReduction::declare_parameters(prm);
    LinearSolverSettings::declare_parameters(prm);
    AugmentedLagrangianSolver::declare_parameters(prm);
    PostprocessorManager<dim>::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
    Q1Floor<dim>::declare_parameters(prm);
    ElasticTiming<dim>::declare_parameters(prm);
    DisplacementCodeComparison<dim>::declare_parameters(prm);
    NestedLevelRunner<dim>::declare_parameters(prm);
    MaterialLoop<dim>::declare_parameters(prm);
  }

  template <int dim>
  HRProblem<dim>::HRProblem(ParameterHandler          &prm,
                            const MPI_Comm             communicator,
                            const CoarserLevelRequest *as_coarser_level)
    : mpi_communicator(communicator)
    , mesh(communicator)
    , nested(communicator)
    , results_(scene, spaces, system, partition)
    , timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
    , memory(communicator)
  {
    scene.parse_parameters(prm);
    spaces.parse_parameters(prm);
    path_choice.parse_parameters(prm);
    reduction.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    contact_solver.parse_parameters(prm, scene.constants);
    postprocessors.parse_parameters(prm, scene.constants);
    output.parse_parameters(prm);
    floor.parse_parameters(prm);
    elastic_timing.parse_parameters(prm);
    displacement_code.parse_parameters(prm);
    nested.parse_parameters(prm);
    material_loop.parse_parameters(prm);
    nested.carries_point_strains =
      material_loop.projects_constraint(scene, spaces.stress_element_name);
    linear_solver.stiffening_compliance = bool(scene.stress_constraint);
    if (const CoarserLevelRequest *request = as_coarser_level)
      {
        coarser_level            = true;
        scene.global_refinements = request->global_refinements;
        nested.take_request(*request);
        path_choice.setting    = request->path == SolutionPath::null_space ?
                                   PathChoice::Setting::null_space :
                                   PathChoice::Setting::condensed;
        floor.enabled          = false;
        elastic_timing.enabled = false;
        contact_solver.relative_tolerance = request->relative_tolerance;
      }
  }

  template <int dim>
  void
  HRProblem<dim>::refine_adaptively(const AdaptiveRefinement<dim> &cycles,
                                    const HRProblem<dim> *previous_cycle)
  {
    scene.adaptive.history = cycles.history;
    scene.adaptive.cycles  = cycles.cycles;
    if (previous_cycle)
      nested.carry_from(previous_cycle->results());
  }

  template <int dim>
  const Results<dim> &
  HRProblem<dim>::results() const
  {
    return results_;
  }

  template <int dim>
  std::string
  HRProblem<dim>::outcome_message() const
  {
    return contact_solver.outcome_message(results_.free_rigid_motions);
  }

  template <int dim>
  void
  HRProblem<dim>::setup(std::ostream &log)
  {
    {
      TimerOutput::Scope t(timer, "mesh and dofs");
      mesh.create(scene,
                  spaces,
                  path_choice,
                  {postprocessors.needs_replicated_mesh(scene),
                   MaterialLoop<dim>::iterates(scene)},
                  partition);
      linear_solver.largest_aspect_ratio  = mesh.largest_aspect_ratio();
      results_.solve.largest_aspect_ratio = mesh.largest_aspect_ratio();
    }
    memory.mark("mesh, dofs and partition");
    mesh.describe(scene, spaces, partition, log);
    {
      TimerOutput::Scope t(timer, "assembly");
      // Where the path is condensed whatever the rows, the free rows of
      // unconstrained nodes can stay implicit; a distributed mesh is always
      // lean.
      const bool lean_rows =
        mesh.distributed() ||
        (path_choice.setting != PathChoice::Setting::null_space &&
         !path_choice.dense_fits_every_dof_free(
           spaces.dof_handler_displacement.n_dofs(),
           spaces.stress_unknowns().n_dofs()));
      HRAssembler<dim>(scene, spaces).classify_rows(system, lean_rows);
      partition.add_dofs_of_rows_across_nodes(system);
    }
    memory.mark("row classification");
    log << "  rows: " << system.n_free_rows << " free (C), "
        << system.contact_rows.size() << " normal (Q), "
        << system.prescribed_rows.size() << " prescribed (H)" << std::endl;
    // The postprocessors' input against the scene, the mesh and the rows (a
    // probe outside the body, an error bound on contact), before the solve.
    if (!coarser_level)
      postprocessors.check_input(scene, mesh.triangulation(), system);
  }

  template <int dim>
  std::unique_ptr<NewtonStepPath>
  HRProblem<dim>::build_path(std::ostream &log)
  {
    TimerOutput::Scope              t(timer, "equilibrium reduction");
    std::unique_ptr<NewtonStepPath> path;
    if (results_.solve.path == SolutionPath::condensed)
      path = std::make_unique<CondensedStep>(system, linear_solver, &partition);
    else
      {
        reduction.initialize(system, &log);
        path                     = std::make_unique<NullSpaceStep>(reduction);
        results_.solve.reduction = &reduction;
      }
    if (coarse_start.size() > 0)
      {
        path->set_start(coarse_start);
        coarse_start.reinit(0);
      }
    return path;
  }

  template <int dim>
  void
  HRProblem<dim>::solve(std::ostream &log)
  {
    Results<dim> &r = results_;
    setup(log);
    r.has_contact = system.has_contact();
    displacement_code.check_scene(scene, r.has_contact);
    r.solve.path = path_choice.choose(
      PathChoice::dense_reduction_bytes(system.n_free_rows,
                                        spaces.stress_unknowns().n_dofs()),
      {contact_solver.regularisation ==
         AugmentedLagrangianSolver::Regularisation::displacement,
       scene.has_changing_rows(),
       mesh.distributed(),
       MaterialLoop<dim>::iterates(scene),
       scene.refined_locally()},
      log);
    const bool condensed = (r.solve.path == SolutionPath::condensed);
    {
      // The condensed path keeps only the blocks the contact rows need.
      TimerOutput::Scope t(timer, "assembly");
      HRAssembler<dim>(scene, spaces)
        .assemble_blocks(system, condensed ? &partition : nullptr);
    }
    memory.mark("equilibrium blocks");
    if (elastic_timing.run(linear_solver, r, log))
      memory.mark("linear elastic solve (timed)");
    if (floor.run(linear_solver, output.print_timing, r, log))
      memory.mark("Q1 floor (timed)");
    Timer contact_timer;
    nested.run(
      r.solve.path, contact_solver, linear_solver, r, coarse_start, log);
    if (!r.coarse_levels.empty())
      memory.mark("coarser levels");
    const std::unique_ptr<NewtonStepPath> path = build_path(log);
    memory.mark("Newton-step path");
    ContactSolve<dim>(contact_solver, material_loop)
      .run(system, *path, r, timer, log);
    r.solve.seconds = contact_timer.wall_time();
    memory.mark("contact solve");
    {
      TimerOutput::Scope t(timer, "displacements");
      recover_fields(*path, r);
    }
    memory.mark("stresses and displacements");
    r.solve.linear_statistics = path->statistics;
    displacement_code.run(material_loop.material_iteration,
                          linear_solver,
                          r,
                          log);
    if (condensed)
      log_linear_statistics(r.solve.linear_statistics,
                            r.solve.largest_aspect_ratio,
                            output.print_timing,
                            log);
    if (!all_finite(r.stress))
      throw InputError("Solve: the stresses are not finite; the problem is "
                       "singular or badly scaled.");
  }

  template <int dim>
  void
  HRProblem<dim>::output_results(std::ostream &log)
  {
    // Never write non-finite fields: stop before the first file instead.
    if (!all_finite(results_.displacement))
      throw NotConvergedError(
        "the displacements are not finite (the solver diverged); no result "
        "file was written. Reduce Augmented Lagrangian/Initial penalty, or "
        "check the supports.");
    TimerOutput::Scope t(timer, "postprocess and output");
    RunSummary<dim>::fill(results_, elastic_timing.enabled, results_.summary);
    results_.wall_time = 0;
    for (const auto &[section, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      results_.wall_time += seconds;
    std::filesystem::create_directories(output.directory);
    PostprocessOutput out{
      results_.summary, log, output.directory, mpi_communicator, {}, {}};
    postprocessors.execute(results_, out);
    if (is_root_process(mpi_communicator))
      results_.summary.write(output.directory + "/summary.txt");
    log << "  results in " << output.directory << "/ (summary.txt";
    for (const std::string &file : out.mentioned_files)
      log << ", " << file;
    log << ")" << std::endl;
  }

  template <int dim>
  void
  HRProblem<dim>::run(std::ostream &log)
  {
    solve(log);
    output_results(log);
    if (output.print_timing && is_root_process(mpi_communicator))
      {
        timer.print_summary();
        memory.print(log);
      }
    if (!results_.converged())
      throw NotConvergedError(outcome_message());
  }

  template class HRProblem<2>;
  template class HRProblem<3>;
} // namespace hrcontact
