#include <deal.II/base/utilities.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/core/hr_problem.h>
#include <hrcontact/core/run.h>
#include <hrcontact/discretisation/displacement_law_stiffness.h>
#include <hrcontact/discretisation/displacement_stiffness.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/discretisation/prolongation.h>
#include <hrcontact/geometry/cell_aspect_ratio.h>
#include <hrcontact/material/linear_elasticity.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  HRProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    Scene<dim>::declare_parameters(prm);
    MixedSpaces<dim>::declare_parameters(prm);
    EquilibriumReduction::declare_parameters(prm);
    LinearSolverSettings::declare_parameters(prm);
    AugmentedLagrangianSolver::declare_parameters(prm);
    PostprocessorManager<dim>::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
    NestedIterationSettings::declare_parameters(prm);
    MaterialIteration::declare_parameters(prm);
    StressConstraintIteration::declare_parameters(prm);
  }

  template <int dim>
  HRProblem<dim>::HRProblem(ParameterHandler &prm, const MPI_Comm communicator)
    : mpi_communicator(communicator)
    , results_(scene, spaces, system, partition)
    , timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
  {
    scene.parse_parameters(prm);
    spaces.parse_parameters(prm);
    reduction.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    contact_solver.parse_parameters(prm, scene.constants);
    postprocessors.parse_parameters(prm, scene.constants);
    output.parse_parameters(prm);
    nested.parse_parameters(prm);
    material_iteration.parse_parameters(prm);
    constraint_iteration.parse_parameters(prm);
    linear_solver.stiffening_compliance = bool(scene.stress_constraint);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    parameter_text = text.str();
  }

  template <int dim>
  const Results<dim> &
  HRProblem<dim>::results() const
  {
    return results_;
  }

  template <int dim>
  void
  HRProblem<dim>::setup(std::ostream &log)
  {
    {
      TimerOutput::Scope t(timer, "mesh and dofs");
      // Several processes on the condensed path: each keeps only its part
      // of the mesh. What needs every cell on every process keeps the
      // serial mesh: the dense null-space path, a random distortion (p4est
      // would distort each part differently) and postprocessors that walk
      // across the whole mesh.
      const unsigned int n_processes =
        Utilities::MPI::job_supports_mpi() ?
          Utilities::MPI::n_mpi_processes(mpi_communicator) :
          1;
      replicated_mesh_reason =
        reduction.path == "null-space" ? "the null-space path" :
        scene.distortion != 0          ? "Geometry/Distortion" :
        postprocessors.needs_replicated_mesh(scene) ?
                                "a postprocessor walks across it" :
                                "";
      distributed_mesh = n_processes > 1 && replicated_mesh_reason.empty();
      if (distributed_mesh)
        triangulation =
          std::make_unique<parallel::distributed::Triangulation<dim>>(
            mpi_communicator);
      else
        triangulation = std::make_unique<Triangulation<dim>>();
      scene.create_mesh(*triangulation);
      spaces.setup(*triangulation);
      // Path = automatic takes the dense null-space path where it fits
      // (choose_path): a mesh that small stays serial, as it needs every
      // cell on every process (the mesh is cheap to build again).
      if (distributed_mesh && reduction.path == "automatic" &&
          !material_iteration_prefers_condensed() &&
          dense_reduction_bytes(spaces.dof_handler_displacement.n_dofs()) <=
            reduction.automatic_dense_limit)
        {
          distributed_mesh       = false;
          replicated_mesh_reason = "small enough for the null-space path";
          // The DoFHandlers move to the new mesh before the old one goes.
          auto serial = std::make_unique<Triangulation<dim>>();
          scene.create_mesh(*serial);
          spaces.setup(*serial);
          triangulation = std::move(serial);
        }
      partition = partition_with_p4est(*triangulation,
                                       spaces.dof_handler_displacement,
                                       mpi_communicator);
      // Stretched cells change how AMG should coarsen (AMG aggregation).
      linear_solver.largest_aspect_ratio =
        largest_cell_aspect_ratio(*triangulation);
      results_.largest_aspect_ratio = linear_solver.largest_aspect_ratio;
    }
    mark_memory("mesh, dofs and partition");
    log << "  "
        << (dim == 2 ? "2D (" + scene.plane_condition_name() + ")" : "3D")
        << ", stress element " << spaces.stress_element_name << '\n'
        << "  mesh: " << triangulation->n_global_active_cells() << " cells, "
        << spaces.dof_handler_displacement.n_dofs() / dim << " nodes\n"
        << "  dofs: " << spaces.dof_handler_displacement.n_dofs()
        << " displacement, " << spaces.stress_unknowns().n_dofs() << " stress"
        << (spaces.has_parameters() ? " parameters" : "") << std::endl;
    if (partition.distributed())
      log << "  parallel: " << partition.describe()
          << (distributed_mesh ?
                ", distributed mesh" :
                ", replicated mesh (" + replicated_mesh_reason + ")")
          << std::endl;
    {
      TimerOutput::Scope t(timer, "assembly");
      // The dense bytes fall as the free rows grow, so with every dof free
      // they bound those of any classification from below: above the limit
      // the path is condensed whatever the rows, and the free rows of
      // unconstrained nodes can stay implicit.
      // A distributed mesh is always lean: no process knows every node.
      const bool lean_rows =
        distributed_mesh ||
        (reduction.path != "null-space" &&
         dense_reduction_bytes(spaces.dof_handler_displacement.n_dofs()) >
           reduction.automatic_dense_limit);
      HRAssembler<dim>(scene, spaces).classify_rows(system, lean_rows);
      // Rows over the nodes of two bodies (contact pairs): the process that
      // owns a row's node also reads and writes the row's other dofs
      // (w = d . u, the held row's constraint, the master rows' fill-in),
      // so they join its relevant dofs. A surface's worth, like the rows.
      if (partition.distributed())
        {
          std::vector<types::global_dof_index> coupled;
          for (const auto &row : system.rows)
            if (system.dof_node(row.combination.front().first) !=
                system.dof_node(row.combination.back().first))
              for (const auto &[dof, c] : row.combination)
                coupled.push_back(dof);
          std::sort(coupled.begin(), coupled.end());
          coupled.erase(std::unique(coupled.begin(), coupled.end()),
                        coupled.end());
          partition.relevant.add_indices(coupled.begin(), coupled.end());
          partition.relevant.compress();
        }
    }
    mark_memory("row classification");
    log << "  rows: " << system.n_free_rows << " free (C), "
        << system.contact_rows.size() << " normal (Q), "
        << system.prescribed_rows.size() << " prescribed (H)" << std::endl;
  }

  template <int dim>
  double
  HRProblem<dim>::dense_reduction_bytes(const double n_free_rows) const
  {
    // C (n x tau), the null-space basis (n x m) and M0 with its factor.
    const double n = n_free_rows, tau = spaces.stress_unknowns().n_dofs();
    const double m = std::max(0., tau - n);
    return 8 * (tau * n + n * m + 2 * m * m);
  }

  template <int dim>
  std::string
  HRProblem<dim>::choose_path(std::ostream &log) const
  {
    // The paper's dense null-space reduction, or the condensed sparse system
    // once the dense one would be too big.
    const double dense_bytes = dense_reduction_bytes(system.n_free_rows);
    std::string  path        = reduction.path;
    const bool   displacement_al =
      (contact_solver.regularisation ==
       AugmentedLagrangianSolver::Regularisation::displacement);
    if (displacement_al && path == "null-space")
      throw InputError(
        "Augmented Lagrangian/Regularisation = displacement augmented "
        "Lagrangian needs Equilibrium reduction/Path = condensed (or "
        "automatic): the null-space path cannot leave a contact node free of "
        "both a spring and a support.");
    const bool relinearise = scene.has_changing_rows();
    if (relinearise && path == "null-space")
      throw InputError(
        "Contact/Update curved obstacles = true needs Equilibrium "
        "reduction/Path = condensed (or automatic): the null-space "
        "reduction is built once from the initial constraint directions.");
    if (displacement_al || relinearise || distributed_mesh)
      path = "condensed";
    std::string why;
    if (path == "automatic" && dense_bytes <= reduction.automatic_dense_limit &&
        material_iteration_prefers_condensed())
      why = "for the material iteration; ";
    if (path == "automatic")
      path = (dense_bytes <= reduction.automatic_dense_limit && why.empty()) ?
               "null-space" :
               "condensed";
    log << "  Newton-step path: " << path << " (" << why
        << "dense reduction would need about " << std::setprecision(3)
        << dense_bytes / 1e9 << " GB)" << std::endl;
    return path;
  }

  template <int dim>
  bool
  HRProblem<dim>::material_iteration_prefers_condensed() const
  {
    return !scene.all_linear() || scene.stress_constraint != nullptr;
  }

  template <int dim>
  void
  HRProblem<dim>::solve(std::ostream &log)
  {
    setup(log);
    Results<dim> &r = results_;
    r.has_contact   = false;
    for (const unsigned int row : system.contact_rows)
      r.has_contact |=
        system.rows[row].unilateral || bool(system.rows[row].law);
    // Refused before any solve: a linear law has nothing to compare, and
    // the displacement code has no contact or stress constraint.
    if (output.compare_displacement_code)
      {
        if (scene.all_linear() || r.has_contact || scene.stress_constraint)
          throw InputError(
            "Output/Compare with a displacement code: only for a nonlinear "
            "material (Material/Model = Ramberg-Osgood) without contact or a "
            "stress constraint.");
      }
    r.solution_path      = choose_path(log);
    const bool condensed = (r.solution_path == "condensed");
    {
      // The condensed path keeps only the blocks the contact rows need.
      TimerOutput::Scope t(timer, "assembly");
      HRAssembler<dim>(scene, spaces)
        .assemble_blocks(system, condensed ? &partition : nullptr);
    }
    mark_memory("equilibrium blocks");
    const unsigned int nq    = system.contact_rows.size();
    r.linear_elastic_seconds = 0;
    if (output.time_linear_solve && condensed)
      {
        // A fresh path, so that nothing is reused from it.
        Timer               elastic_timer;
        std::vector<double> p;
        CondensedStep(system, linear_solver, &partition)
          .solve(std::vector<bool>(nq, false),
                 std::vector<double>(nq, 0.),
                 std::vector<double>(nq, 1.),
                 p);
        r.linear_elastic_seconds = elastic_timer.wall_time();
        log << "  one linear elastic solve (contact rows held at their gaps): "
            << r.linear_elastic_seconds << " s" << std::endl;
      }
    if (output.time_linear_solve && condensed)
      mark_memory("linear elastic solve (timed)");
    if (output.time_floor)
      {
        time_floor(log);
        mark_memory("Q1 floor (timed)");
      }
    Timer contact_timer;
    start_from_coarser_level(r.solution_path, log);
    if (!r.coarse_levels.empty())
      mark_memory("coarser levels");
    std::unique_ptr<NewtonStepPath> path;
    {
      TimerOutput::Scope t(timer, "equilibrium reduction");
      if (condensed)
        path =
          std::make_unique<CondensedStep>(system, linear_solver, &partition);
      else
        {
          reduction.initialize(system, &log);
          path        = std::make_unique<NullSpaceStep>(reduction);
          r.reduction = &reduction;
        }
    }
    if (coarse_start.size() > 0)
      {
        path->set_start(coarse_start);
        coarse_start.reinit(0);
      }
    mark_memory("Newton-step path");
    solve_on_path(*path, log);
    r.contact_solve_seconds = contact_timer.wall_time();
    mark_memory("contact solve");
    {
      TimerOutput::Scope t(timer, "displacements");
      collect_fields(*path);
    }
    mark_memory("stresses and displacements");
    r.linear_statistics = path->statistics;
    if (output.compare_displacement_code)
      compare_displacement_code(log);
    if (condensed)
      log << "  linear solver: " << r.linear_statistics.solver << ", "
          << r.linear_statistics.solves << " solves"
          << (r.linear_statistics.solver == "cg-amg" ?
                ", " + std::to_string(r.linear_statistics.iterations) +
                  " CG iterations, " +
                  std::to_string(r.linear_statistics.preconditioner_setups) +
                  " AMG set-ups, aggregates by " +
                  r.linear_statistics.aggregation +
                  " (largest cell aspect ratio " +
                  std::to_string(int(std::round(r.largest_aspect_ratio))) +
                  ")" :
                std::string());
    if (condensed && output.print_timing)
      log << " (set-ups " << r.linear_statistics.setup_seconds << " s, solves "
          << r.linear_statistics.solve_seconds << " s)";
    if (condensed && r.linear_statistics.tightenings > 0)
      log << ", tolerance tightened " << r.linear_statistics.tightenings
          << " time(s) to " << r.linear_statistics.tolerance;
    if (condensed)
      log << std::endl;
    bool finite = true;
    for (const double v : r.stress)
      finite &= std::isfinite(v);
    if (Utilities::MPI::min(int(finite), r.stress.get_mpi_communicator()) == 0)
      throw InputError("Solve: the stresses are not finite; the problem is "
                       "singular or badly scaled.");
  }

  template <int dim>
  void
  HRProblem<dim>::time_floor(std::ostream &log)
  {
    // The same supports, processes, CG, AMG and tolerance; K from the
    // displacement bilinear form. Timed from assembly to solution.
    Results<dim>        &r     = results_;
    const unsigned int   nq    = system.contact_rows.size();
    LinearSolverSettings floor = linear_solver;
    floor.solver               = "cg-amg";
    floor.reuse_preconditioner = "false";
    Timer                            timer;
    const DisplacementStiffness<dim> q1(scene, spaces);
    CondensedStep                    path(system, floor, &partition, &q1);
    std::vector<double>              p;
    path.solve(std::vector<bool>(nq, false),
               std::vector<double>(nq, 0.),
               std::vector<double>(nq, 1.),
               p);
    r.floor_seconds    = timer.wall_time();
    r.floor_iterations = path.statistics.iterations;
    std::vector<double> w(nq);
    for (unsigned int k = 0; k < nq; ++k)
      w[k] = system.rows[system.contact_rows[k]].value;
    reinit_field(r.floor_displacement, spaces.dof_handler_displacement);
    path.displacements(w, r.floor_displacement);
    log << "  Q1 floor (plain displacement solve, CG + AMG): "
        << r.floor_seconds << " s, " << r.floor_iterations << " CG iterations";
    if (output.print_timing)
      log << " (assembly and AMG set-up " << path.statistics.setup_seconds
          << " s, CG " << path.statistics.solve_seconds << " s)";
    log << std::endl;
  }

  template <int dim>
  void
  HRProblem<dim>::compare_displacement_code(std::ostream &log)
  {
    Results<dim> &r = results_;
    // solve() refused other scenes before solving.
    Assert(!scene.all_linear() && !r.has_contact && !scene.stress_constraint,
           ExcInternalError());
    // Newton on u from zero, each step's stiffness and load from the law
    // inverted at the Gauss points; the run's supports, processes and
    // linear solver. The first step is the elastic one.
    Timer                         timer;
    DisplacementLawStiffness<dim> law(scene, spaces);
    const unsigned int            nq = system.contact_rows.size();
    std::vector<double>           p, w(nq);
    FieldVector                   u, next;
    reinit_field(u, spaces.dof_handler_displacement);
    reinit_field(next, spaces.dof_handler_displacement);
    // The material iteration's stop: the tolerance, or the round-off floor
    // of the solves (here of the total displacements, near 1e-10 of them).
    std::vector<double> changes{1.};
    r.displacement_code_steps       = 0;
    r.displacement_code_local_steps = 0;
    while (changes.back() > material_iteration.relative_tolerance &&
           !MaterialIteration::at_roundoff(changes,
                                           material_iteration.roundoff_ceiling))
      {
        if (r.displacement_code_steps >= material_iteration.maximum_steps)
          throw NotConvergedError(
            "Output/Compare with a displacement code: no convergence in " +
            std::to_string(material_iteration.maximum_steps) +
            " Newton steps (Material iteration/Maximum steps).");
        r.displacement_code_local_steps =
          std::max(r.displacement_code_local_steps, law.linearise_at(u));
        CondensedStep path(system, linear_solver, &partition, &law);
        path.solve(std::vector<bool>(nq, false),
                   std::vector<double>(nq, 0.),
                   std::vector<double>(nq, 1.),
                   p);
        path.displacements(w, next);
        ++r.displacement_code_steps;
        FieldVector difference;
        difference.reinit(next, true);
        difference.copy_locally_owned_data_from(next);
        difference.add(-1., u);
        const double scale = next.linfty_norm();
        changes.push_back(scale > 0 ? difference.linfty_norm() / scale : 0.);
        log << "  displacement code, Newton step " << r.displacement_code_steps
            << ": displacement change " << std::scientific
            << std::setprecision(2) << changes.back() << std::defaultfloat
            << std::setprecision(6) << std::endl;
        u.copy_locally_owned_data_from(next);
        if (!is_complete(u))
          u.update_ghost_values();
      }
    r.displacement_code_seconds = timer.wall_time();
    FieldVector difference;
    difference.reinit(u, true);
    difference.copy_locally_owned_data_from(u);
    difference.add(-1., r.displacement);
    r.displacement_code_difference =
      difference.linfty_norm() / std::max(r.displacement.linfty_norm(), 1e-300);
    log << "  displacement code: " << r.displacement_code_steps
        << " Newton steps, at most " << r.displacement_code_local_steps
        << " local steps to invert the law at a Gauss point, "
        << r.displacement_code_seconds << " s (the stress code's solve "
        << r.contact_solve_seconds << " s); displacements differ by "
        << std::scientific << std::setprecision(3)
        << r.displacement_code_difference << std::defaultfloat
        << std::setprecision(6) << " of the largest" << std::endl;
  }

  template <int dim>
  void
  HRProblem<dim>::start_from_coarser_level(const std::string &path_name,
                                           std::ostream      &log)
  {
    Results<dim> &r = results_;
    r.coarse_levels.clear();
    const bool has_contact = r.has_contact;
    using Regularisation   = AugmentedLagrangianSolver::Regularisation;
    const bool carries_state =
      (contact_solver.regularisation == Regularisation::consistent ||
       contact_solver.regularisation == Regularisation::macaulay);
    // Automatic levels for the consistent AL only: the Macaulay AL's kink
    // at p = 0 makes its diagonal scheme cycle from a carried state (Hertz
    // at 24,962 dofs, doc/speed-accuracy.md); a number of levels still
    // applies to it.
    // Nor for a nonlinear law or a stress constraint: a coarse level would
    // run the whole material iteration to carry the contact state only,
    // which each material step's contact solve starts from anyway (the
    // no-tension pier at 128 x 768 cells: 760 s of coarse levels, the fine
    // level's iteration the same; doc/materials.md).
    const bool applies =
      has_contact && path_name == "condensed" &&
      contact_solver.regularisation == Regularisation::consistent &&
      !scene.has_changing_rows() && scene.all_linear() &&
      !scene.stress_constraint;
    const unsigned int levels = nested.levels(scene.global_refinements,
                                              system.n_displacement_dofs,
                                              dim,
                                              applies);
    if (levels == 0)
      return;
    if (!has_contact)
      return; // nothing to carry: one linear solve
    if (!carries_state)
      throw InputError(
        "Nested iteration/Coarse levels: the pure penalty and the "
        "displacement augmented Lagrangian have no multipliers to carry to "
        "the next level; set Coarse levels = 0 (or automatic).");
    if (scene.has_changing_rows())
      throw InputError(
        "Nested iteration/Coarse levels: curved obstacles that follow the "
        "configuration (Contact/Update curved obstacles) change their rows "
        "between levels; set Coarse levels = 0 (or automatic).");
    if (levels > scene.global_refinements)
      throw InputError("Nested iteration/Coarse levels = " +
                       std::to_string(levels) + " needs at least as many " +
                       "Geometry/Global refinements (the scene has " +
                       std::to_string(scene.global_refinements) + ").");

    // The coarser level: the same scene with one refinement fewer, on the
    // same path and processes, nested further itself; no timing extras.
    Timer            timer;
    ParameterHandler coarse_parameters;
    declare_all_parameters(coarse_parameters);
    coarse_parameters.parse_input_from_string(parameter_text);
    HRProblem<dim> coarse(coarse_parameters, mpi_communicator);
    coarse.scene.global_refinements = scene.global_refinements - 1;
    coarse.nested.coarse_levels     = levels - 1;
    coarse.finest_level             = false;
    coarse.reduction.path           = path_name;
    coarse.output.time_floor        = false;
    coarse.output.time_linear_solve = false;
    coarse.contact_solver.relative_tolerance =
      nested.coarse_tolerance(contact_solver.relative_tolerance);
    std::ostringstream coarse_log;
    bool               solved = false;
    std::string        failure;
    try
      {
        coarse.solve(coarse_log);
        solved = coarse.results().converged();
        if (!solved)
          failure = coarse.contact_solver.outcome_message(
            coarse.results().free_rigid_motions);
      }
    catch (const std::exception &e)
      {
        failure = e.what();
      }
    r.coarse_levels = coarse.results().coarse_levels;
    typename Results<dim>::CoarseLevel level;
    level.global_refinements = coarse.scene.global_refinements;
    level.displacement_dofs  = coarse.system.n_displacement_dofs;
    if (const ContactIteration *c = coarse.results().contact)
      {
        level.updates      = c->history.size();
        level.newton_steps = c->total_newton_steps;
      }
    level.linear_solves = coarse.results().linear_statistics.solves;
    level.converged     = solved;
    // Its own time: the coarser levels it solved first report theirs.
    level.seconds = timer.wall_time();
    for (const auto &inner : r.coarse_levels)
      level.seconds -= inner.seconds;
    r.coarse_levels.push_back(level);
    // The coarser levels' own lines first (coarsest first).
    {
      std::istringstream lines(coarse_log.str());
      for (std::string line; std::getline(lines, line);)
        if (line.rfind("  nested iteration, level", 0) == 0)
          log << line << '\n';
    }
    log << "  nested iteration, level of " << level.global_refinements
        << " refinements: " << level.displacement_dofs << " dofs, "
        << level.updates << " updates, " << level.newton_steps
        << " Newton steps, " << std::setprecision(3) << level.seconds << " s"
        << (solved ? "" :
                     " (did not converge; the next level starts from "
                     "the trial solution: " +
                       failure + ")")
        << std::endl;
    if (!solved)
      return;
    // The nodal compliance of the finer mesh against the coarser one (2D:
    // the same; 3D: twice), and reactions per tributary area.
    const double compliance_scale =
      scene.nodal_compliance(*triangulation) /
      coarse.scene.nodal_compliance(*coarse.triangulation);
    contact_solver.start_from(transfer_contact_state(coarse.system,
                                                     *coarse.results().contact,
                                                     system,
                                                     std::pow(2., 1. - dim),
                                                     compliance_scale,
                                                     !finest_level));
    linear_solver.starts_from_coarser_level = true;
    // CG's first guess: the coarser answer, about an h^2 error away in
    // displacement (Hertz refinement 9: the first fine solve takes 77 CG
    // iterations instead of 100 from zero).
    if (nested.carry_displacements && path_name == "condensed" &&
        linear_solver.choose(system.n_displacement_dofs, dim) == "cg-amg")
      {
        reinit_field(coarse_start, spaces.dof_handler_displacement);
        prolongate_to_finer_mesh(coarse.spaces.dof_handler_displacement,
                                 coarse.results().displacement,
                                 spaces.dof_handler_displacement,
                                 coarse_start);
      }
  }

  template <int dim>
  void
  HRProblem<dim>::solve_on_path(NewtonStepPath &path, std::ostream &log)
  {
    Results<dim>      &r  = results_;
    const unsigned int nq = system.contact_rows.size();
    r.contact             = nullptr;
    r.contact_w.assign(nq, 0.);
    if (!r.has_contact)
      {
        // Without contact every rigid motion must be held by a support: a
        // sparse direct solver may return a vector for the singular system
        // without a word (the null-space reduction stops earlier on its
        // rank deficiency).
        const unsigned int free = rigid_motions_held_only_by_contact(system);
        if (free > 0)
          throw InputError(
            "Supports: " + std::to_string(free) +
            " rigid-body motion(s) of the body are held by no support (the "
            "body floats). Prescribe displacements or normal constraints that "
            "stop every translation and rotation.");
        TimerOutput::Scope  t(timer, "solve");
        std::vector<double> p;
        auto                linear_solve = [&]() {
          path.solve(std::vector<bool>(nq, false),
                     std::vector<double>(nq, 0.),
                     std::vector<double>(nq, 1.),
                     p);
        };
        solve_material(path, linear_solve, log);
        for (unsigned int k = 0; k < nq; ++k)
          r.contact_w[k] = system.rows[system.contact_rows[k]].value;
        return;
      }
    TimerOutput::Scope t(timer, "augmented Lagrangian");
    // The largest nodal load (distributed: the largest on any process).
    const double load_scale = system.load.linfty_norm();
    contact_solver.set_nodal_compliance(scene.nodal_compliance(*triangulation));
    // The bodies only contact holds along some rigid motion, each with the
    // contact rows at its nodes (a pair row at both bodies').
    {
      const auto free      = rigid_motions_held_only_by_contact_by_body(system);
      r.free_rigid_motions = std::accumulate(free.begin(), free.end(), 0u);
      auto &held           = contact_solver.held_only_by_contact;
      held.clear();
      std::vector<int> index(free.size(), -1);
      for (unsigned int b = 0; b < free.size(); ++b)
        if (free[b] > 0)
          {
            index[b] = held.size();
            held.push_back(
              {free.size() > 1 ? "body " + std::to_string(b + 1) : "",
               free[b],
               {}});
          }
      auto body_of = [this](const unsigned int node) {
        const auto it = system.node_body.find(node);
        return it == system.node_body.end() ? 0u : it->second;
      };
      for (unsigned int i = 0; i < nq; ++i)
        {
          std::set<unsigned int> bodies;
          for (const auto &[dof, c] :
               system.rows[system.contact_rows[i]].combination)
            bodies.insert(body_of(system.dof_node(dof)));
          for (const unsigned int b : bodies)
            if (b < index.size() && index[b] >= 0)
              held[index[b]].rows.push_back(i);
        }
    }
    // Kinds whose rows follow the configuration (curved obstacles).
    std::vector<std::unique_ptr<RowRelinearisation>> relinearisations;
    for (const auto &source : scene.constraints)
      if (auto r = source->relinearisation(system))
        relinearisations.push_back(std::move(r));
    AssertThrow(relinearisations.size() <= 1,
                ExcMessage("one kind of constraint rows that follow the "
                           "configuration per scene"));
    auto contact_solve = [&]() {
      if (relinearisations.empty())
        contact_solver.solve(system, path, load_scale, log);
      else
        contact_solver.solve(
          system, path, load_scale, *relinearisations.front(), log);
    };
    // A nonlinear law or a stress constraint: each material Newton step is
    // a whole augmented Lagrangian solve at the compliances and strain terms
    // of the last stresses, started (consistent and Macaulay AL) from the
    // previous step's multipliers, compliances and reactions, so that the
    // later steps take one or two updates. When the stresses stop changing,
    // the law and the contact conditions hold together.
    const bool carries_state =
      (contact_solver.regularisation ==
         AugmentedLagrangianSolver::Regularisation::consistent ||
       contact_solver.regularisation ==
         AugmentedLagrangianSolver::Regularisation::macaulay);
    bool first = true;
    solve_material(
      path,
      [&]() {
        if (!first && carries_state)
          {
            const ContactIteration &last = contact_solver.result();
            ContactStart            start;
            start.mu              = last.mu;
            start.alpha           = last.alpha;
            start.p               = last.p;
            start.tolerance_scale = last.tolerance_scale;
            start.scale_per_level = last.scale_per_level;
            start.origin          = "the last material step's state";
            contact_solver.start_from(start);
          }
        first = false;
        contact_solve();
        if (!contact_solver.result().converged() &&
            (!scene.all_linear() || scene.stress_constraint))
          throw NotConvergedError(
            "Material iteration, step " +
            std::to_string(material_iteration.n_steps() + 1) +
            ": the contact iteration did not converge: " +
            contact_solver.outcome_message(r.free_rigid_motions));
      },
      log);
    r.contact = &contact_solver.result();
    // After the last multiplier update mu = w_n - g (pressed: mu = 0).
    for (unsigned int k = 0; k < nq; ++k)
      r.contact_w[k] =
        system.rows[system.contact_rows[k]].value + r.contact->opening[k];
  }

  template <int dim>
  void
  HRProblem<dim>::solve_material(NewtonStepPath              &path,
                                 const std::function<void()> &solve_once,
                                 std::ostream                &log)
  {
    Results<dim> &r  = results_;
    r.material_steps = 0;
    r.material_changes.clear();
    r.constraint_residuals.clear();
    r.constraint_inner_steps.clear();
    r.constraint_field     = nullptr;
    const bool constrained = static_cast<bool>(scene.stress_constraint);
    if (scene.all_linear() && !constrained)
      {
        solve_once();
        return;
      }
    // Newton on the complementary energy: F_c and d_c refreshed at the last
    // stresses (on a distributed mesh each process those of its own and
    // ghost cells, all the cells it assembles).
    HRAssembler<dim> assembler(scene, spaces);
    if (constrained)
      {
        constraint_field = std::make_unique<StressConstraintField<dim>>(
          *scene.stress_constraint,
          spaces,
          constraint_iteration.constraint_points == "vertices" ?
            StressConstraintField<dim>::Points::vertices :
          constraint_iteration.constraint_points == "Gauss points" ?
            StressConstraintField<dim>::Points::gauss_points :
            StressConstraintField<dim>::Points::cell_centres);
        assembler.constraint_field = constraint_field.get();
      }
    MaterialIteration::Operations operations;
    operations.solve    = solve_once;
    operations.stresses = [&](FieldVector &s) {
      reinit_field(s, spaces.stress_unknowns());
      path.stresses(s);
    };
    operations.linearise_at = [&](const FieldVector &s) {
      assembler.refresh_flexibility(system, s);
      path.flexibility_changed();
    };
    const auto run_material_iteration = [&]() {
      material_iteration.solve(operations, log);
      r.material_steps += material_iteration.n_steps();
      r.material_changes.insert(r.material_changes.end(),
                                material_iteration.change_history().begin(),
                                material_iteration.change_history().end());
    };
    if (!constrained)
      {
        run_material_iteration();
        log << "  material iteration: " << r.material_steps << " Newton steps"
            << std::endl;
        return;
      }

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
      run_material_iteration();
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
    const LinearElasticity<dim> *elastic = scene.material->elastic_part();
    log << "  stress constraint '" << scene.stress_constraint->name() << "' at "
        << constraint_field->quadrature().size() << " point(s) per cell ("
        << constraint_iteration.constraint_points
        << "), consistent augmented Lagrangian" << std::endl;
    constraint_iteration.solve(c,
                               elastic ? 1. / elastic->youngs_modulus() : 1.,
                               log);
    r.constraint_residuals    = constraint_iteration.residual_history();
    r.constraint_inner_steps  = constraint_iteration.inner_step_history();
    r.cracked_fraction        = constraint_field->cracked_fraction();
    r.largest_fracture_strain = constraint_field->largest_opening();
    r.constraint_field        = constraint_field.get();
    log << "  stress constraint: " << r.constraint_residuals.size()
        << " multiplier updates, " << r.material_steps
        << " material Newton steps, cracked fraction " << r.cracked_fraction
        << std::endl;
  }

  template <int dim>
  void
  HRProblem<dim>::collect_fields(const NewtonStepPath &path)
  {
    Results<dim> &r = results_;
    // The solver's stress unknowns; Results::stress holds their values
    // (the same vector unless the stress element has parameters).
    FieldVector unknowns;
    reinit_field(unknowns, spaces.stress_unknowns());
    path.stresses(unknowns);
    reinit_field(r.stress, spaces.dof_handler_stress);
    spaces.expand(unknowns, r.stress);
    reinit_field(r.displacement, spaces.dof_handler_displacement);
    path.displacements(r.contact_w, r.displacement);
    // The reactions B~_r s - f~_r, each computed by the owner of its node
    // (on a distributed mesh only it has every cell around the node).
    // Several processes: a master node's row may hold alpha n at a slave
    // node of a contact pair (ContactPairs::couple_rows), whose cells its
    // owner does not have; that part is alpha times the pair row's p (the
    // slave's other rows are free: no residual), from the Q rows first.
    std::map<unsigned int, unsigned int> pair_row_at;
    if (partition.distributed())
      for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
        {
          const EquilibriumRow &row = system.rows[system.contact_rows[k]];
          if (system.dof_node(row.combination.front().first) !=
              system.dof_node(row.combination.back().first))
            pair_row_at[row.node] = k;
        }
    auto reactions = [&](const std::vector<unsigned int> &rows,
                         std::vector<double>             &values) {
      values.assign(rows.size(), 0.);
      for (unsigned int k = 0; k < rows.size(); ++k)
        {
          const EquilibriumRow &row = system.rows[rows[k]];
          if (!partition.owned.is_element(row.combination.front().first))
            continue;
          if (pair_row_at.empty())
            {
              values[k] =
                system.row_times(row, unknowns) - system.row_load(row);
              continue;
            }
          EquilibriumRow own = row, other;
          own.combination.clear();
          own.direction.clear();
          std::map<unsigned int, double> alpha;
          for (unsigned int e = 0; e < row.combination.size(); ++e)
            {
              const auto [dof, c] = row.combination[e];
              if (c == 0) // a pair row's master entries
                continue;
              if (system.dof_node(dof) == row.node)
                own.combination.emplace_back(dof, c);
              else
                {
                  const unsigned int    slave = system.dof_node(dof);
                  const EquilibriumRow &q =
                    system.rows[system.contact_rows[pair_row_at.at(slave)]];
                  // c = alpha n over the slave's dofs; n = d_q there.
                  alpha[slave] +=
                    c * q.direction_component(system.dof_component(dof));
                }
            }
          values[k] = system.row_times(own, unknowns) - system.row_load(own);
          for (const auto &[slave, a] : alpha)
            values[k] += a * r.contact_reactions[pair_row_at.at(slave)];
        }
      if (partition.distributed())
        Utilities::MPI::sum(values, partition.communicator, values);
    };
    reactions(system.contact_rows, r.contact_reactions);
    reactions(system.prescribed_rows, r.support_reactions);
    if (spaces.has_parameters())
      r.stress_parameters.swap(unknowns);
    else
      r.stress_parameters.reinit(0);
    // The node displacement of each Q row, by the owner of its node.
    const unsigned int  nq = system.contact_rows.size();
    std::vector<double> node_u(3 * nq, 0.);
    for (unsigned int k = 0; k < nq; ++k)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[k]];
        if (partition.owned.is_element(row.combination.front().first))
          for (unsigned int d = 0; d < dim; ++d)
            node_u[3 * k + d] = r.displacement(row.combination[d].first);
      }
    if (partition.distributed())
      Utilities::MPI::sum(node_u, partition.communicator, node_u);
    r.contact_node_displacement.assign(nq, {{0., 0., 0.}});
    for (unsigned int k = 0; k < nq; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        r.contact_node_displacement[k][d] = node_u[3 * k + d];
  }

  template <int dim>
  void
  HRProblem<dim>::summarise_run()
  {
    const Results<dim> &r       = results_;
    Summary            &summary = results_.summary;
    summary                     = Summary();
    summary.add("dimension", dim);
    summary.add("plane_condition", scene.plane_condition_name());
    summary.add("stress_element", spaces.stress_element_name);
    summary.add("cells", triangulation->n_global_active_cells());
    summary.add("largest_aspect_ratio", r.largest_aspect_ratio);
    summary.add("displacement_dofs", system.n_displacement_dofs);
    summary.add("stress_dofs", system.n_stress_dofs);
    summary.add("free_rows", system.n_free_rows);
    summary.add("normal_rows", system.contact_rows.size());
    summary.add("prescribed_rows", system.prescribed_rows.size());
    summary.add("solution_path", r.solution_path);
    if (r.solution_path == "condensed")
      {
        const LinearSolverStatistics &s = r.linear_statistics;
        summary.add("linear_solver", s.solver);
        summary.add("linear_solves", s.solves);
        summary.add("linear_iterations", s.iterations);
        summary.add("preconditioner_setups", s.preconditioner_setups);
        if (s.solver == "cg-amg")
          {
            summary.add("linear_tolerance", s.tolerance);
            summary.add("amg_aggregation", s.aggregation);
            summary.add("linear_tolerance_tightenings", s.tightenings);
          }
        summary.add("linear_setup_seconds", s.setup_seconds);
        summary.add("linear_solve_seconds", s.solve_seconds);
        if (output.time_linear_solve)
          summary.add("linear_elastic_solve_seconds", r.linear_elastic_seconds);
      }
    if (r.reduction)
      summary.add("self_equilibrated_stresses",
                  r.reduction->n_self_equilibrated());
    summary.add("contact_constraints",
                r.contact ? r.contact->p.size() : std::size_t(0));
    summary.add("iterations", r.contact ? r.contact->history.size() : 0);
    summary.add("newton_steps", r.contact ? r.contact->total_newton_steps : 0);
    summary.add("converged", r.converged() ? "true" : "false");
    if (!scene.all_linear() || scene.stress_constraint)
      {
        summary.add("material_newton_steps", r.material_steps);
        summary.add("material_stress_change",
                    r.material_changes.empty() ? 0. :
                                                 r.material_changes.back());
      }
    if (scene.stress_constraint)
      {
        summary.add("stress_constraint", scene.stress_constraint->name());
        summary.add("stress_constraint_updates", r.constraint_residuals.size());
        summary.add("stress_constraint_residual",
                    r.constraint_residuals.empty() ?
                      0. :
                      r.constraint_residuals.back());
        summary.add(dim == 2 ? "cracked_area_fraction" :
                               "cracked_volume_fraction",
                    r.cracked_fraction);
        summary.add("largest_fracture_strain", r.largest_fracture_strain);
      }
    if (!r.coarse_levels.empty())
      {
        unsigned int newton = 0, solves = 0;
        double       seconds = 0;
        for (const auto &level : r.coarse_levels)
          {
            newton += level.newton_steps;
            solves += level.linear_solves;
            seconds += level.seconds;
          }
        summary.add("nested_coarse_levels", r.coarse_levels.size());
        summary.add("coarse_level_newton_steps", newton);
        summary.add("coarse_level_linear_solves", solves);
        summary.add("coarse_level_seconds", seconds);
      }
  }

  template <int dim>
  void
  HRProblem<dim>::output_results(std::ostream &log)
  {
    // Never write non-finite fields: stop before the first file instead.
    bool finite = true;
    for (const double v : results_.displacement)
      finite &= std::isfinite(v);
    if (Utilities::MPI::min(int(finite),
                            results_.displacement.get_mpi_communicator()) == 0)
      throw NotConvergedError(
        "the displacements are not finite (the solver diverged); no result "
        "file was written. Reduce Augmented Lagrangian/Initial penalty, or "
        "check the supports.");
    TimerOutput::Scope t(timer, "postprocess and output");
    summarise_run();
    results_.wall_time = 0;
    for (const auto &[section, seconds] :
         timer.get_summary_data(TimerOutput::total_wall_time))
      results_.wall_time += seconds;
    std::filesystem::create_directories(output.directory);
    PostprocessOutput out{
      results_.summary, log, output.directory, mpi_communicator, {}};
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
  HRProblem<dim>::mark_memory(const std::string &stage)
  {
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    memory_marks.emplace_back(
      stage,
      Utilities::MPI::max(stats.VmRSS / 1024., mpi_communicator),
      Utilities::MPI::max(stats.VmHWM / 1024., mpi_communicator));
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
        std::ostringstream table;
        table << "resident memory after each stage (MB, largest process):\n";
        for (const auto &[stage, resident, peak] : memory_marks)
          table << "  " << std::left << std::setw(36) << stage << std::right
                << std::setw(10) << std::fixed << std::setprecision(0)
                << resident << "   (peak so far " << peak << ")\n";
        log << table.str() << std::flush;
      }
    if (!results_.converged())
      throw NotConvergedError(
        contact_solver.outcome_message(results_.free_rigid_motions));
  }

  template class HRProblem<2>;
  template class HRProblem<3>;
} // namespace hrcontact
