#include <deal.II/base/timer.h>

#include <hrcontact/adaptivity/cycle_state_transfer.h>
#include <hrcontact/core/hr_problem.h>
#include <hrcontact/core/run.h>
#include <hrcontact/discretisation/prolongation.h>
#include <hrcontact/solvers/nested_level_runner.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  NestedLevelRunner<dim>::NestedLevelRunner(const MPI_Comm communicator)
    : communicator(communicator)
  {}

  template <int dim>
  void
  NestedLevelRunner<dim>::declare_parameters(ParameterHandler &prm)
  {
    NestedIterationSettings::declare_parameters(prm);
  }

  template <int dim>
  void
  NestedLevelRunner<dim>::parse_parameters(ParameterHandler &prm)
  {
    settings.parse_parameters(prm);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    parameter_text = text.str();
  }

  template <int dim>
  void
  NestedLevelRunner<dim>::take_request(const CoarserLevelRequest &request)
  {
    settings.coarse_levels = request.coarse_levels;
    finest_level           = false;
  }

  template <int dim>
  void
  NestedLevelRunner<dim>::carry_from(const Results<dim> &previous)
  {
    previous_cycle = &previous;
  }

  template <int dim>
  bool
  NestedLevelRunner<dim>::carries_state(
    const SolutionPath               path,
    const AugmentedLagrangianSolver &contact_solver,
    const Results<dim>              &r) const
  {
    using Regularisation    = AugmentedLagrangianSolver::Regularisation;
    const Scene<dim> &scene = r.scene;
    return r.has_contact && path == SolutionPath::condensed &&
           contact_solver.regularisation == Regularisation::consistent &&
           !scene.has_changing_rows() && scene.all_linear() &&
           !scene.stress_constraint;
  }

  template <int dim>
  bool
  NestedLevelRunner<dim>::nests(const SolutionPath               path,
                                const AugmentedLagrangianSolver &contact_solver,
                                const Results<dim>              &r) const
  {
    // The closed-form projection's Newton iteration is carried by its
    // point strains: the crack pattern of the coarser level is most of the
    // finer one's (doc/materials.md, steps per level).
    if (carries_point_strains)
      return path == SolutionPath::condensed &&
             (!r.has_contact ||
              contact_solver.regularisation ==
                AugmentedLagrangianSolver::Regularisation::consistent) &&
             !r.scene.has_changing_rows();
    return carries_state(path, contact_solver, r);
  }

  template <int dim>
  unsigned int
  NestedLevelRunner<dim>::levels_to_solve(
    const SolutionPath               path,
    const AugmentedLagrangianSolver &contact_solver,
    const Results<dim>              &r) const
  {
    const Scene<dim> &scene = r.scene;
    // Automatic levels for the consistent AL only: the Macaulay AL's kink
    // at p = 0 makes its diagonal scheme cycle from a carried state (Hertz
    // at 24,962 dofs, doc/speed-accuracy.md); a number of levels still
    // applies to it.
    // Nor for a nonlinear law or a stress constraint: a coarse level would
    // run the whole material iteration to carry the contact state only,
    // which each material step's contact solve starts from anyway (the
    // no-tension pier at 128 x 768 cells: 760 s of coarse levels, the fine
    // level's iteration the same; doc/materials.md). The closed-form
    // projection is the exception: its coarser levels carry the point
    // strains, which save the finer level most of its steps (nests()).
    const bool         applies = nests(path, contact_solver, r);
    const unsigned int levels  = settings.levels(scene.global_refinements,
                                                r.system.n_displacement_dofs,
                                                dim,
                                                applies);
    // Without contact or point strains nothing to carry.
    if (levels == 0 || !(r.has_contact || carries_point_strains))
      return 0;
    if (r.has_contact && !contact_solver.carries_state())
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
    return levels;
  }

  template <int dim>
  void
  NestedLevelRunner<dim>::run(const SolutionPath         path,
                              AugmentedLagrangianSolver &contact_solver,
                              LinearSolverSettings      &linear_solver,
                              Results<dim>              &r,
                              FieldVector               &coarse_start,
                              std::ostream              &log) const
  {
    r.coarse_levels.clear();
    if (previous_cycle && previous_cycle->converged() &&
        previous_cycle->contact && carries_state(path, contact_solver, r))
      {
        // An adaptive cycle: the previous cycle's mesh is the coarser level.
        contact_solver.start_from(carry_contact_state(*previous_cycle, r));
        linear_solver.starts_from_coarser_level = true;
        start_displacements(
          *previous_cycle, path, linear_solver, r, coarse_start);
        return;
      }
    const unsigned int levels = levels_to_solve(path, contact_solver, r);
    if (levels == 0)
      return;

    // The coarser level: the same scene with one refinement fewer, on the
    // same path and processes, nested further itself; no timing extras.
    Timer            timer;
    ParameterHandler coarse_parameters;
    declare_all_parameters(coarse_parameters);
    coarse_parameters.parse_input_from_string(parameter_text);
    CoarserLevelRequest request;
    request.global_refinements = r.scene.global_refinements - 1;
    request.coarse_levels      = levels - 1;
    request.path               = path;
    request.relative_tolerance =
      settings.coarse_tolerance(contact_solver.relative_tolerance);
    HRProblem<dim>     coarse(coarse_parameters, communicator, &request);
    std::ostringstream coarse_log;
    bool               solved = false;
    std::string        failure;
    try
      {
        coarse.solve(coarse_log);
        solved = coarse.results().converged();
        if (!solved)
          failure = coarse.outcome_message();
      }
    catch (const std::exception &e)
      {
        failure = e.what();
      }
    const Results<dim> &c = coarse.results();
    r.coarse_levels       = c.coarse_levels;
    typename Results<dim>::CoarseLevel level;
    level.global_refinements = c.scene.global_refinements;
    level.displacement_dofs  = c.system.n_displacement_dofs;
    if (c.contact)
      {
        level.updates      = c.contact->history.size();
        level.newton_steps = c.contact->total_newton_steps;
      }
    level.linear_solves  = c.solve.linear_statistics.solves;
    level.material_steps = c.material.newton_steps;
    level.converged      = solved;
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
        << " Newton steps, "
        << (carries_point_strains ?
              std::to_string(level.material_steps) + " material steps, " :
              "")
        << std::setprecision(3) << level.seconds << " s"
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
      r.scene.nodal_compliance(r.triangulation()) /
      c.scene.nodal_compliance(c.triangulation());
    if (c.contact)
      contact_solver.start_from(transfer_contact_state(c.system,
                                                       *c.contact,
                                                       r.system,
                                                       std::pow(2., 1. - dim),
                                                       compliance_scale,
                                                       !finest_level));
    if (carries_point_strains)
      carry_point_strains(c, r);
    linear_solver.starts_from_coarser_level = true;
    start_displacements(c, path, linear_solver, r, coarse_start);
  }

  template <int dim>
  void
  NestedLevelRunner<dim>::carry_point_strains(const Results<dim> &c,
                                              Results<dim>       &r) const
  {
    // The answer, the interior point's strains at Carried initial barrier
    // (a start over, MaterialLoop::run_barrier_path) and the stress scale.
    r.stress_constraint.elastic_stress = c.stress_constraint.elastic_stress;
    FieldVector &start = r.stress_constraint.start_point_strains;
    reinit_field(start, r.spaces.stress_unknowns());
    prolongate_to_finer_mesh(c.spaces.stress_unknowns(),
                             c.stress_constraint.point_strains,
                             r.spaces.stress_unknowns(),
                             start);
    const FieldVector &path       = c.stress_constraint.carried_point_strains;
    FieldVector       &path_start = r.stress_constraint.start_path_strains;
    path_start.reinit(0);
    if (path.size() > 0)
      {
        reinit_field(path_start, r.spaces.stress_unknowns());
        prolongate_to_finer_mesh(c.spaces.stress_unknowns(),
                                 path,
                                 r.spaces.stress_unknowns(),
                                 path_start);
      }
  }

  template <int dim>
  void
  NestedLevelRunner<dim>::start_displacements(
    const Results<dim>         &coarse,
    const SolutionPath          path,
    const LinearSolverSettings &linear_solver,
    const Results<dim>         &r,
    FieldVector                &coarse_start) const
  {
    // CG's first guess: the coarser answer, about an h^2 error away in
    // displacement (Hertz refinement 9: the first fine solve takes 77 CG
    // iterations instead of 100 from zero). Not between meshes of
    // different coarse grids (a serial mesh of several bodies joins refined
    // bodies): CG then starts from zero.
    if (settings.carry_displacements && path == SolutionPath::condensed &&
        coarse.triangulation().n_cells(0) == r.triangulation().n_cells(0) &&
        linear_solver.choose(r.system.n_displacement_dofs, dim) ==
          LinearSolverKind::cg_amg)
      {
        reinit_field(coarse_start, r.spaces.dof_handler_displacement);
        prolongate_to_finer_mesh(coarse.spaces.dof_handler_displacement,
                                 coarse.displacement,
                                 r.spaces.dof_handler_displacement,
                                 coarse_start);
      }
  }

  template class NestedLevelRunner<2>;
  template class NestedLevelRunner<3>;
} // namespace hrcontact
