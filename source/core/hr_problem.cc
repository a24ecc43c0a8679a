#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/core/hr_problem.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/solvers/newton_step.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  void
  OutputSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::Anything(),
                      "Directory for summary.txt and solution.vtu, relative "
                      "to the working directory; created if missing.");
    prm.declare_entry("Write solution",
                      "true",
                      Patterns::Bool(),
                      "Write solution.vtu (displacement, stress tensor, "
                      "principal stresses, von Mises) for ParaView.");
    prm.declare_entry("Print timing",
                      "true",
                      Patterns::Bool(),
                      "Print a table of wall times at the end of the run "
                      "(tests switch it off to keep their output "
                      "reproducible).");
    prm.declare_entry(
      "Time a linear elastic solve",
      "false",
      Patterns::Bool(),
      "Benchmarks: before the contact iteration, solve the condensed system "
      "once more with every contact row held at its gap (a linear elastic "
      "problem on the same mesh and processes, from a fresh matrix and "
      "preconditioner) and report its wall time as "
      "linear_elastic_solve_seconds beside contact_solve_seconds in "
      "summary.txt. Condensed path only; costs one extra solve.");
    prm.leave_subsection();

    // Contact postprocessing lives with the other postprocessing entries.
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Hertz load",
      "",
      Patterns::Anything(),
      "2D contact: the total load per unit length P on the full cylinder of a "
      "Hertz problem (an expression of the constants). With Hertz radius set, "
      "summary.txt compares contact_half_width and peak_pressure with "
      "hertz_half_width = sqrt(4 P R / (pi E*)) and hertz_peak_pressure = 2 "
      "P / (pi a), E* = E/(1 - nu^2). Empty: no comparison.");
    prm.declare_entry("Hertz radius",
                      "",
                      Patterns::Anything(),
                      "The cylinder radius R of the Hertz comparison.");
    prm.declare_entry(
      "Tracked contact nodes",
      "",
      Patterns::Anything(),
      "Points 'x, y [, z]' separated by '|': the nearest contact node of each "
      "gets its normal displacement and reaction at every multiplier update "
      "written to contact-history.csv (k, node, x, y, w_n, p_n, alpha, "
      "status).");
    prm.declare_entry(
      "Lining sections",
      "120",
      Patterns::Integer(2, 100000),
      "tunnel_lining grids: number of intervals between section stations "
      "along the mid-line (equally spaced in arc length; stations in the "
      "short stretch around the arcs' joint are skipped). lining.csv gets N, "
      "V, M and the displacement at each station.");
    prm.declare_entry(
      "Lining reference principal stresses",
      "",
      Patterns::Anything(),
      "tunnel_lining grids: extremes of principal stresses to compare with, "
      "'min of s_min : max of s_min : min of s_max : max of s_max', "
      "expressions of the constants in the scene's stress unit (e.g. the "
      "paper's Fig. 12 values converted). summary.txt lists them next to "
      "ours. Empty: no comparison.");
    prm.leave_subsection();
  }

  void
  OutputSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory         = prm.get("Output directory");
    write_vtu         = prm.get_bool("Write solution");
    print_timing      = prm.get_bool("Print timing");
    time_linear_solve = prm.get_bool("Time a linear elastic solve");
    prm.leave_subsection();
    prm.enter_subsection("Postprocess");
    hertz_load      = prm.get("Hertz load");
    hertz_radius    = prm.get("Hertz radius");
    tracked_nodes   = prm.get("Tracked contact nodes");
    lining_sections = prm.get_integer("Lining sections");
    lining_reference_principal_stresses =
      prm.get("Lining reference principal stresses");
    prm.leave_subsection();
  }

  template <int dim>
  void
  HRProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    Scene<dim>::declare_parameters(prm);
    MixedSpaces<dim>::declare_parameters(prm);
    EquilibriumReduction::declare_parameters(prm);
    LinearSolverSettings::declare_parameters(prm);
    AugmentedLagrangianSolver::declare_parameters(prm);
    Postprocessor<dim>::declare_parameters(prm);
    OutputSettings::declare_parameters(prm);
  }

  template <int dim>
  HRProblem<dim>::HRProblem(ParameterHandler &prm, const MPI_Comm communicator)
    : mpi_communicator(communicator)
    , timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
  {
    scene.parse_parameters(prm);
    spaces.parse_parameters(prm);
    reduction.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    contact_solver.parse_parameters(prm, scene.constants);
    postprocessor.parse_parameters(prm, scene.constants);
    output.parse_parameters(prm);
  }

  template <int dim>
  void
  HRProblem<dim>::solve(std::ostream &log)
  {
    {
      TimerOutput::Scope t(timer, "mesh and dofs");
      scene.create_mesh(triangulation);
      spaces.setup(triangulation);
      partition = partition_with_p4est(triangulation,
                                       spaces.dof_handler_displacement,
                                       mpi_communicator);
    }
    log << "  "
        << (dim == 2 ? "2D (" + scene.plane_condition_name() + ")" : "3D")
        << ", stress element " << spaces.stress_element_name << '\n'
        << "  mesh: " << triangulation.n_active_cells() << " cells, "
        << triangulation.n_used_vertices() << " nodes\n"
        << "  dofs: " << spaces.dof_handler_displacement.n_dofs()
        << " displacement, " << spaces.dof_handler_stress.n_dofs() << " stress"
        << std::endl;
    if (partition.distributed())
      log << "  parallel: " << partition.describe() << std::endl;

    const HRAssembler<dim> assembler(scene, spaces);
    {
      TimerOutput::Scope t(timer, "assembly");
      assembler.classify_rows(system);
    }
    log << "  rows: " << system.free_rows.size() << " free (C), "
        << system.contact_rows.size() << " normal (Q), "
        << system.prescribed_rows.size() << " prescribed (H)" << std::endl;

    // The path of the Newton steps: the paper's dense null-space reduction,
    // or the condensed sparse system once the dense one would be too big.
    {
      const double n           = system.free_rows.size(),
                   tau         = spaces.dof_handler_stress.n_dofs();
      const double m           = std::max(0., tau - n);
      const double dense_bytes = 8 * (tau * n + n * m + 2 * m * m);
      solution_path            = reduction.path;
      const bool displacement_al =
        (contact_solver.regularisation ==
         AugmentedLagrangianSolver::Regularisation::displacement);
      if (displacement_al && solution_path == "null-space")
        throw InputError(
          "Augmented Lagrangian/Regularisation = displacement augmented "
          "Lagrangian needs Equilibrium reduction/Path = condensed (or "
          "automatic): the null-space path cannot leave a contact node free of "
          "both a spring and a support.");
      const bool relinearise =
        scene.update_curved_obstacles && !scene.curved_obstacles.empty();
      if (relinearise && solution_path == "null-space")
        throw InputError(
          "Contact/Update curved obstacles = true needs Equilibrium "
          "reduction/Path = condensed (or automatic): the null-space "
          "reduction is built once from the initial constraint directions.");
      if (displacement_al || relinearise)
        solution_path = "condensed";
      if (solution_path == "automatic")
        solution_path = (dense_bytes <= reduction.automatic_dense_limit) ?
                          "null-space" :
                          "condensed";
      log << "  Newton-step path: " << solution_path
          << " (dense reduction would "
          << "need about " << std::setprecision(3) << dense_bytes / 1e9
          << " GB)" << std::endl;
    }
    {
      // The condensed path keeps only the blocks the contact rows need.
      TimerOutput::Scope t(timer, "assembly");
      assembler.assemble_blocks(system,
                                solution_path == "condensed" ? &partition :
                                                               nullptr);
    }
    const unsigned int nq  = system.contact_rows.size();
    linear_elastic_seconds = 0;
    if (output.time_linear_solve && solution_path == "condensed")
      {
        // A fresh path, so that nothing is reused from it.
        Timer               elastic_timer;
        std::vector<double> p;
        CondensedStep(system, linear_solver, &partition)
          .solve(std::vector<bool>(nq, false),
                 std::vector<double>(nq, 0.),
                 std::vector<double>(nq, 1.),
                 p);
        linear_elastic_seconds = elastic_timer.wall_time();
        log << "  one linear elastic solve (contact rows held at their gaps): "
            << linear_elastic_seconds << " s" << std::endl;
      }
    Timer                           contact_timer;
    std::unique_ptr<NewtonStepPath> path;
    {
      TimerOutput::Scope t(timer, "equilibrium reduction");
      if (solution_path == "null-space")
        {
          reduction.initialize(system, &log);
          path = std::make_unique<NullSpaceStep>(reduction);
        }
      else
        path =
          std::make_unique<CondensedStep>(system, linear_solver, &partition);
    }
    has_contact = false;
    for (const unsigned int r : system.contact_rows)
      has_contact |= system.rows[r].unilateral || system.rows[r].law;
    contact_w.assign(nq, 0.);
    if (has_contact)
      {
        TimerOutput::Scope t(timer, "augmented Lagrangian");
        double             load_scale = 0;
        for (unsigned int i = 0; i < system.load.size(); ++i)
          load_scale = std::max(load_scale, std::abs(system.load[i]));
        // Nodal compliance c_h: (1 - nu^2)/E in plane strain, 1/E in plane
        // stress, 1/(E h) in 3D with h the mean cell size.
        double c_h = 1 / scene.youngs_modulus;
        if (dim == 2 && scene.plane_strain)
          c_h *= 1 - scene.poisson_ratio * scene.poisson_ratio;
        if (dim == 3)
          {
            double volume = 0;
            for (const auto &cell : triangulation.active_cell_iterators())
              volume += cell->measure();
            c_h /= std::cbrt(volume / triangulation.n_active_cells());
          }
        contact_solver.set_nodal_compliance(c_h);
        free_rigid_motions = rigid_motions_held_only_by_contact(system);
        contact_solver.held_only_by_contact = (free_rigid_motions > 0);
        if (scene.update_curved_obstacles && !scene.curved_obstacles.empty())
          contact_solver.after_update = [this, &path]() {
            return relinearise_curved_obstacles(*path);
          };
        contact_solver.solve(system, *path, load_scale, log);
        contact_solver.after_update = nullptr;
        // After the last multiplier update mu = w_n - g (pressed: mu = 0).
        for (unsigned int k = 0; k < nq; ++k)
          contact_w[k] = system.rows[system.contact_rows[k]].value +
                         contact_solver.opening[k];
      }
    else
      {
        TimerOutput::Scope  t(timer, "solve");
        std::vector<double> p;
        path->solve(std::vector<bool>(nq, false),
                    std::vector<double>(nq, 0.),
                    std::vector<double>(nq, 1.),
                    p);
        for (unsigned int k = 0; k < nq; ++k)
          contact_w[k] = system.rows[system.contact_rows[k]].value;
      }
    contact_solve_seconds = contact_timer.wall_time();
    {
      TimerOutput::Scope t(timer, "displacements");
      path->stresses(stress);
      path->displacements(contact_w, displacement);
    }
    linear_statistics = path->statistics;
    if (solution_path == "condensed")
      log << "  linear solver: " << linear_statistics.solver << ", "
          << linear_statistics.solves << " solves"
          << (linear_statistics.solver == "cg-amg" ?
                ", " + std::to_string(linear_statistics.iterations) +
                  " CG iterations, " +
                  std::to_string(linear_statistics.preconditioner_setups) +
                  " AMG set-ups" :
                std::string())
          << std::endl;

    contact_reactions.clear();
    for (const unsigned int r : system.contact_rows)
      contact_reactions.push_back(system.row_times(system.rows[r], stress) -
                                  system.row_load(system.rows[r]));
    support_reactions.clear();
    for (const unsigned int r : system.prescribed_rows)
      support_reactions.push_back(system.row_times(system.rows[r], stress) -
                                  system.row_load(system.rows[r]));

    for (const double v : stress)
      if (!std::isfinite(v))
        throw InputError("Solve: the stresses are not finite; the problem is "
                         "singular or badly scaled.");
  }

  template <int dim>
  void
  HRProblem<dim>::output_results(std::ostream &log)
  {
    // Never write non-finite fields: stop before the first file instead.
    for (const double v : displacement)
      if (!std::isfinite(v))
        throw NotConvergedError(
          "the displacements are not finite (the solver diverged); no result "
          "file was written. Reduce Augmented Lagrangian/Initial penalty, or "
          "check the supports.");
    TimerOutput::Scope t(timer, "postprocess and output");
    summary = Summary();
    summary.add("dimension", dim);
    summary.add("plane_condition", scene.plane_condition_name());
    summary.add("stress_element", spaces.stress_element_name);
    summary.add("cells", triangulation.n_active_cells());
    summary.add("displacement_dofs", system.n_displacement_dofs);
    summary.add("stress_dofs", system.n_stress_dofs);
    summary.add("free_rows", system.free_rows.size());
    summary.add("normal_rows", system.contact_rows.size());
    summary.add("prescribed_rows", system.prescribed_rows.size());
    summary.add("solution_path", solution_path);
    if (solution_path == "condensed")
      {
        summary.add("linear_solver", linear_statistics.solver);
        summary.add("linear_solves", linear_statistics.solves);
        summary.add("linear_iterations", linear_statistics.iterations);
        summary.add("preconditioner_setups",
                    linear_statistics.preconditioner_setups);
        summary.add("linear_setup_seconds", linear_statistics.setup_seconds);
        summary.add("linear_solve_seconds", linear_statistics.solve_seconds);
        if (output.time_linear_solve)
          summary.add("linear_elastic_solve_seconds", linear_elastic_seconds);
      }
    if (solution_path == "null-space")
      summary.add("self_equilibrated_stresses",
                  reduction.n_self_equilibrated());
    summary.add("contact_constraints",
                has_contact ? contact_solver.p.size() : std::size_t(0));
    summary.add("iterations", has_contact ? contact_solver.history.size() : 0);
    summary.add("newton_steps",
                has_contact ? contact_solver.total_newton_steps : 0);
    summary.add("converged",
                (!has_contact || contact_solver.converged) ? "true" : "false");

    // Global balance: the reactions (forces the supports exert on the body)
    // and the applied loads sum to zero to round-off.
    // Scale: the largest nodal force involved, so that a self-balanced
    // problem (zero net load) is judged against its reactions.
    std::vector<double> load(dim, 0.), reaction(dim, 0.);
    double              scale = 0;
    // The directions d_r of a node are the primal basis to the dual basis
    // c_r of the rows: sum_r (f.c_r) d_r = f.
    for (const auto &row : system.rows)
      {
        const double f_r = system.row_load(row);
        scale            = std::max(scale, std::abs(f_r));
        for (unsigned int d = 0; d < dim; ++d)
          load[d] += f_r * row.direction_component(d);
      }
    auto add_reaction = [&](const unsigned int r, const double value) {
      scale = std::max(scale, std::abs(value));
      for (unsigned int d = 0; d < dim; ++d)
        reaction[d] += value * system.rows[r].direction_component(d);
    };
    for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
      add_reaction(system.contact_rows[k], contact_reactions[k]);
    for (unsigned int k = 0; k < system.prescribed_rows.size(); ++k)
      add_reaction(system.prescribed_rows[k], support_reactions[k]);
    double      imbalance = 0;
    const char *xyz       = "xyz";
    for (unsigned int d = 0; d < dim; ++d)
      {
        summary.add(std::string("total_load_") + xyz[d], load[d]);
        summary.add(std::string("total_reaction_") + xyz[d], reaction[d]);
        imbalance = std::max(imbalance, std::abs(load[d] + reaction[d]));
      }
    summary.add("equilibrium_imbalance",
                scale > 0 ? imbalance / scale : imbalance);
    double max_p = 0;
    for (const double p : contact_reactions)
      max_p = std::max(max_p, std::abs(p));
    summary.add("max_abs_p_n", max_p);
    if (has_contact)
      {
        // Signorini conditions on the unilateral rows (eq. 12).
        double max_p_positive = 0, max_penetration = 0, max_complementarity = 0;
        unsigned int pressed = 0;
        for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
          if (system.rows[system.contact_rows[k]].unilateral)
            {
              const double p = contact_reactions[k];
              const double gap =
                contact_w[k] - system.rows[system.contact_rows[k]].value;
              max_p_positive  = std::max(max_p_positive, p);
              max_penetration = std::max(max_penetration, gap);
              max_complementarity =
                std::max(max_complementarity, std::abs(p * gap));
              pressed += !contact_solver.released[k];
            }
        summary.add("pressed_constraints", pressed);
        summary.add("final_norm_pbar", contact_solver.final_norm_pbar);
        summary.add("tolerance", contact_solver.tolerance_used);
        summary.add("max_positive_p_n", max_p_positive);
        summary.add("max_penetration", max_penetration);
        summary.add("max_complementarity", max_complementarity);

        // Two-sided stops: which node sits on which branch of its law.
        std::map<unsigned int, std::pair<unsigned int, std::string>> branches;
        const TwoSidedStop *any = nullptr;
        for (const unsigned int k : sorted_stop_rows())
          {
            const auto *stop = dynamic_cast<const TwoSidedStop *>(
              system.rows[system.contact_rows[k]].law.get());
            any = stop;
            const auto &c =
              system.node_coordinates[system.rows[system.contact_rows[k]].node];
            auto &entry = branches[contact_solver.pieces[k].branch];
            std::ostringstream where;
            where << std::setprecision(6) << " (" << c[0];
            for (unsigned int d = 1; d < dim; ++d)
              where << ", " << c[d];
            where << ")";
            ++entry.first;
            entry.second += where.str();
          }
        if (any)
          {
            const char *keys[5] = {"stops_free",
                                   "stops_at_upper_stop",
                                   "stops_beyond_upper",
                                   "stops_at_lower_stop",
                                   "stops_beyond_lower"};
            for (unsigned int b = 0; b < 5; ++b)
              {
                const auto it = branches.find(b);
                summary.add(keys[b],
                            it == branches.end() ?
                              std::string("0") :
                              std::to_string(it->second.first) + " at" +
                                it->second.second);
              }
          }
      }
    double max_u = 0;
    for (unsigned int i = 0; i < displacement.size(); i += 1)
      max_u = std::max(max_u, std::abs(displacement[i]));
    summary.add("max_abs_displacement_component", max_u);

    log << "  total load     (";
    for (unsigned int d = 0; d < dim; ++d)
      log << (d ? ", " : "") << std::setprecision(6) << load[d];
    log << ")\n  total reaction (";
    for (unsigned int d = 0; d < dim; ++d)
      log << (d ? ", " : "") << std::setprecision(6) << reaction[d];
    log << ")" << std::endl;

    postprocessor.evaluate(spaces, scene, displacement, stress, summary, log);

    std::filesystem::create_directories(output.directory);
    std::string solution_file;
    if (output.write_vtu)
      solution_file = postprocessor.write_solution(
        spaces, scene, displacement, stress, partition, output.directory);
    if (has_contact)
      summary.add("contact_solve_seconds", contact_solve_seconds);
    {
      // Peak resident memory, summed over the processes.
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      double peak = stats.VmHWM / 1024.;
      if (partition.distributed())
        peak = Utilities::MPI::sum(peak, partition.communicator);
      summary.add("peak_memory_MB", peak);
    }
    summary.add(
      "wall_time",
      timer.get_summary_data(TimerOutput::total_wall_time).empty() ?
        0. :
        [this] {
          double sum = 0;
          for (const auto &[k, v] :
               timer.get_summary_data(TimerOutput::total_wall_time))
            sum += v;
          return sum;
        }());
    if constexpr (dim == 2)
      if (scene.lining)
        lining_output(log);
    if (has_contact)
      {
        if (!scene.lining)
          contact_pressure_summary(log);
        write_contact_tables();
      }
    if (is_root_process(mpi_communicator))
      summary.write(output.directory + "/summary.txt");
    log << "  results in " << output.directory << "/ (summary.txt"
        << (output.write_vtu ? ", " + solution_file : "") << ")" << std::endl;
  }

  template <int dim>
  std::vector<unsigned int>
  HRProblem<dim>::sorted_q_rows(
    const std::function<bool(const EquilibriumRow &)> &select) const
  {
    std::vector<unsigned int> order;
    for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
      if (select(system.rows[system.contact_rows[k]]))
        order.push_back(k);
    auto coordinates = [this](const unsigned int k) {
      return system.node_coordinates[system.rows[system.contact_rows[k]].node];
    };
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](unsigned int a, unsigned int b) {
                       return coordinates(a) < coordinates(b);
                     });
    return order;
  }

  template <int dim>
  std::vector<unsigned int>
  HRProblem<dim>::sorted_contact_rows() const
  {
    return sorted_q_rows(
      [](const EquilibriumRow &row) { return row.unilateral; });
  }

  template <int dim>
  bool
  HRProblem<dim>::relinearise_curved_obstacles(const NewtonStepPath &path)
  {
    // The tangent obstacle at the point of the surface nearest to the
    // current position X + u of each node (the straight case of eq. 10 at
    // the current configuration): new normal n, gap g = (x_surface - X).n,
    // with the prescribed components of the node taken out as the assembler
    // does; the node's free rows complete the basis again.
    Vector<double> u;
    path.displacements(contact_w, u);
    const double                                      u_max   = u.linfty_norm();
    bool                                              changed = false;
    std::map<unsigned int, std::vector<unsigned int>> rows_of_node;
    for (unsigned int r = 0; r < system.rows.size(); ++r)
      rows_of_node[system.rows[r].node].push_back(r);
    for (const unsigned int r : system.contact_rows)
      {
        EquilibriumRow &row = system.rows[r];
        const auto      co  = scene.curved_obstacles.find(row.obstacle);
        // Corner nodes (several obstacles) stay linearised at the start.
        if (row.obstacle < 0 || co == scene.curved_obstacles.end() ||
            !row.direction.empty())
          continue;
        Point<dim> X, x;
        for (unsigned int d = 0; d < dim; ++d)
          {
            X[d] = system.node_coordinates[row.node][d];
            x[d] = X[d] + u[row.combination[d].first];
          }
        const auto [surface, n]            = co->second.project(x);
        Tensor<1, dim>              n_free = n;
        double                      g      = (surface - X) * n;
        std::vector<Tensor<1, dim>> taken;
        for (const unsigned int s : rows_of_node[row.node])
          if (system.rows[s].row_class == RowClass::prescribed)
            for (unsigned int d = 0; d < dim; ++d)
              if (system.rows[s].combination[d].second == 1.)
                {
                  g -= n[d] * system.rows[s].value;
                  n_free[d] = 0;
                  Tensor<1, dim> e;
                  e[d] = 1;
                  taken.push_back(e);
                }
        const double length = n_free.norm();
        if (length < 1e-8)
          continue;
        n_free /= length;
        g /= length;
        // Changed: beyond 1e-8 of the displacements (the finite-difference
        // gradient of a level set is good to about that).
        double turn = 0;
        for (unsigned int d = 0; d < dim; ++d)
          turn += std::abs(n_free[d] - row.combination[d].second);
        if (std::abs(g - row.value) + turn * u_max >
            1e-8 * (u_max + std::abs(g)))
          changed = true;
        for (unsigned int d = 0; d < dim; ++d)
          row.combination[d].second = n_free[d];
        row.value = g;
        taken.push_back(n_free);
        // The free rows: the orthogonal complement, as the assembler has it.
        const auto   complement = orthogonal_complement<dim>(taken);
        unsigned int next       = 0;
        for (const unsigned int s : rows_of_node[row.node])
          if (system.rows[s].row_class == RowClass::free &&
              next < complement.size())
            {
              for (unsigned int d = 0; d < dim; ++d)
                system.rows[s].combination[d].second = complement[next][d];
              ++next;
            }
      }
    return changed;
  }

  template <int dim>
  std::vector<unsigned int>
  HRProblem<dim>::sorted_stop_rows() const
  {
    return sorted_q_rows([](const EquilibriumRow &row) {
      return dynamic_cast<const TwoSidedStop *>(row.law.get()) != nullptr;
    });
  }

  template <int dim>
  void
  HRProblem<dim>::contact_pressure_summary(std::ostream &log)
  {
    if (dim != 2)
      return;
    // Pressure at a node = -p / (half the lengths of its two neighbouring
    // contact edges): the nodal reaction spread over its tributary length.
    // Assumes the contact boundary is one curve, monotone in x.
    const std::vector<unsigned int> order = sorted_contact_rows();
    const unsigned int              nc    = order.size();
    auto                            point = [&](const unsigned int j) {
      const auto &c =
        system
          .node_coordinates[system.rows[system.contact_rows[order[j]]].node];
      return Point<2>(c[0], c[1]);
    };
    double peak = 0, zone_end = 0;
    bool   any_pressed = false;
    for (unsigned int j = 0; j < nc; ++j)
      {
        const double left = (j > 0) ? point(j).distance(point(j - 1)) : 0.;
        const double right =
          (j + 1 < nc) ? point(j).distance(point(j + 1)) : 0.;
        const double       tributary = 0.5 * (left + right);
        const unsigned int k         = order[j];
        if (!contact_solver.released[k] && tributary > 0)
          {
            any_pressed = true;
            peak        = std::max(peak, -contact_reactions[k] / tributary);
            // The zone ends halfway to the next open node.
            zone_end = point(j)[0] +
                       ((j + 1 < nc && contact_solver.released[order[j + 1]]) ?
                          0.5 * (point(j + 1)[0] - point(j)[0]) :
                          0.);
          }
      }
    double zone_start = 0;
    for (unsigned int j = 0; j < nc; ++j)
      if (!contact_solver.released[order[j]])
        {
          zone_start = point(j)[0] -
                       ((j > 0) ? 0.5 * (point(j)[0] - point(j - 1)[0]) : 0.);
          break;
        }
    summary.add("peak_pressure", any_pressed ? peak : 0.);
    summary.add("contact_zone_x_min", zone_start);
    summary.add("contact_zone_x_max", zone_end);
    if (Utilities::trim(output.hertz_load).empty() ||
        Utilities::trim(output.hertz_radius).empty())
      return;
    // Plane strain Hertz contact of a cylinder on a rigid plane; the half
    // model's pressed zone starts at the symmetry plane.
    const double P       = evaluate_constant_expression(output.hertz_load,
                                                  scene.constants,
                                                  "Postprocess/Hertz load");
    const double R       = evaluate_constant_expression(output.hertz_radius,
                                                  scene.constants,
                                                  "Postprocess/Hertz radius");
    const double nu      = scene.poisson_ratio;
    const double E_star  = scene.youngs_modulus / (1 - nu * nu);
    const double a_hertz = std::sqrt(4 * P * R / (numbers::PI * E_star));
    const double p_hertz = 2 * P / (numbers::PI * a_hertz);
    const double a       = zone_end - zone_start;
    summary.add("contact_half_width", a);
    summary.add("hertz_half_width", a_hertz);
    summary.add("relative_error_half_width", (a - a_hertz) / a_hertz);
    summary.add("hertz_peak_pressure", p_hertz);
    summary.add("relative_error_peak_pressure", (peak - p_hertz) / p_hertz);
    log << "  Hertz: half width " << std::setprecision(5) << a << " (Hertz "
        << a_hertz << ", error " << std::setprecision(3)
        << 100 * (a - a_hertz) / a_hertz << " %), peak pressure "
        << std::setprecision(5) << peak << " (Hertz " << p_hertz << ", error "
        << std::setprecision(3) << 100 * (peak - p_hertz) / p_hertz << " %)"
        << std::endl;
  }

  template <int dim>
  void
  HRProblem<dim>::write_contact_tables() const
  {
    // contact.csv: one row per unilateral constraint, sorted by x, y (, z).
    const std::vector<unsigned int> order = sorted_contact_rows();
    const char                     *xyz   = "xyz";
    write_file_atomically(
      mpi_communicator,
      output.directory + "/contact.csv",
      [&](std::ostream &out) {
        for (unsigned int d = 0; d < dim; ++d)
          out << xyz[d] << ",";
        for (unsigned int d = 0; d < dim; ++d)
          out << "n" << xyz[d] << ",";
        out << "gap,";
        for (unsigned int d = 0; d < dim; ++d)
          out << "u" << xyz[d] << ",";
        out << "w_n,";
        for (unsigned int d = 0; d < dim; ++d)
          out << "reaction_" << xyz[d] << ",";
        out << "p_n,mu,alpha,status\n";
        out << std::setprecision(12);
        for (const unsigned int k : order)
          {
            const EquilibriumRow &row = system.rows[system.contact_rows[k]];
            for (unsigned int d = 0; d < dim; ++d)
              out << system.node_coordinates[row.node][d] << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << row.direction_component(d) << ",";
            out << row.value << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << displacement[row.combination[d].first] << ",";
            out << contact_w[k] << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << contact_reactions[k] * row.direction_component(d) << ",";
            out << contact_reactions[k] << "," << contact_solver.mu[k] << ","
                << contact_solver.alpha[k] << ","
                << (contact_solver.released[k] ? "open" : "contact") << "\n";
          }
      });
    // stops.csv: one row per two-sided stop, sorted by x, y (, z).
    const std::vector<unsigned int> stop_order = sorted_stop_rows();
    if (!stop_order.empty())
      write_file_atomically(
        mpi_communicator,
        output.directory + "/stops.csv",
        [&](std::ostream &out) {
          for (unsigned int d = 0; d < dim; ++d)
            out << xyz[d] << ",";
          for (unsigned int d = 0; d < dim; ++d)
            out << "d" << xyz[d] << ",";
          out << "g_minus,g_plus,p0_minus,p0_plus,k_minus,k_plus,w,";
          for (unsigned int d = 0; d < dim; ++d)
            out << "reaction_" << xyz[d] << ",";
          out << "p,mu,alpha,branch\n";
          out << std::setprecision(12);
          for (const unsigned int k : stop_order)
            {
              const EquilibriumRow &row = system.rows[system.contact_rows[k]];
              const auto &stop = dynamic_cast<const TwoSidedStop &>(*row.law);
              double      w    = 0;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  out << system.node_coordinates[row.node][d] << ",";
                  w += row.combination[d].second *
                       displacement[row.combination[d].first];
                }
              for (unsigned int d = 0; d < dim; ++d)
                out << row.combination[d].second << ",";
              out << stop.g_minus << "," << stop.g_plus << "," << stop.p0_minus
                  << "," << stop.p0_plus << "," << stop.k_minus << ","
                  << stop.k_plus << "," << w << ",";
              for (unsigned int d = 0; d < dim; ++d)
                out << contact_reactions[k] * row.combination[d].second << ",";
              out << contact_reactions[k] << "," << contact_solver.mu[k] << ","
                  << contact_solver.alpha[k] << ","
                  << stop.branch_name(contact_solver.pieces[k].branch) << "\n";
            }
        });
    if (!Utilities::trim(output.tracked_nodes).empty())
      {
        // The nearest contact node of each tracked point.
        std::vector<unsigned int> tracked;
        for (const std::string &text :
             split_and_trim(output.tracked_nodes, '|'))
          {
            const auto coords = split_and_trim(text, ',');
            if (coords.size() != dim)
              throw InputError("Postprocess/Tracked contact nodes: '" + text +
                               "' is not a point with " + std::to_string(dim) +
                               " coordinates.");
            std::array<double, 3> x = {{0, 0, 0}};
            for (unsigned int d = 0; d < dim; ++d)
              x[d] = evaluate_constant_expression(
                coords[d],
                scene.constants,
                "Postprocess/Tracked contact nodes");
            double       best    = std::numeric_limits<double>::max();
            unsigned int nearest = order.front();
            for (const unsigned int k : order)
              {
                const auto &c =
                  system
                    .node_coordinates[system.rows[system.contact_rows[k]].node];
                double dist = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  dist += (c[d] - x[d]) * (c[d] - x[d]);
                if (dist < best)
                  {
                    best    = dist;
                    nearest = k;
                  }
              }
            tracked.push_back(nearest);
          }
        write_file_atomically(
          mpi_communicator,
          output.directory + "/contact-history.csv",
          [&](std::ostream &out) {
            out << "k,node,x,y" << (dim == 3 ? ",z" : "")
                << ",w_n,p_n,alpha,status\n"
                << std::setprecision(12);
            for (unsigned int it = 0; it < contact_solver.p_history.size();
                 ++it)
              for (unsigned int t = 0; t < tracked.size(); ++t)
                {
                  const unsigned int k   = tracked[t];
                  const auto        &row = system.rows[system.contact_rows[k]];
                  out << it + 1 << "," << t + 1;
                  for (unsigned int d = 0; d < dim; ++d)
                    out << "," << system.node_coordinates[row.node][d];
                  out << "," << row.value + contact_solver.mu_history[it][k]
                      << "," << contact_solver.p_history[it][k] << ","
                      << contact_solver.alpha_history[it][k] << ","
                      << (contact_solver.released_history[it][k] ? "open" :
                                                                   "contact")
                      << "\n";
                }
          });
      }
    write_file_atomically(
      mpi_communicator,
      output.directory + "/history.csv",
      [&](std::ostream &out) {
        out
          << "k,newton_steps,alpha_min,alpha_max,eps_k,norm_pbar,active_changes,"
             "seconds\n";
        out << std::setprecision(8);
        for (const auto &h : contact_solver.history)
          out << h.k << "," << h.newton_steps << "," << h.alpha_min << ","
              << h.alpha_max << "," << h.eps_k << "," << h.norm_pbar << ","
              << h.active_changes << "," << h.seconds << "\n";
      });
  }

  template <int dim>
  std::string
  HRProblem<dim>::mechanism_hint() const
  {
    if (free_rigid_motions == 0)
      return "";
    return " Note: only the contacts hold this body along " +
           std::to_string(free_rigid_motions) +
           " rigid-body motion(s); if the loads pull it off its obstacles, no "
           "equilibrium exists (a mechanism).";
  }

  template <int dim>
  void
  HRProblem<dim>::run(std::ostream &log)
  {
    solve(log);
    output_results(log);
    if (output.print_timing && is_root_process(mpi_communicator))
      timer.print_summary();
    if (has_contact && contact_solver.floating)
      throw NotConvergedError(
        "every contact constraint released at multiplier update " +
        std::to_string(contact_solver.floating_update) +
        ", and nothing else holds the body: the supports leave " +
        std::to_string(free_rigid_motions) +
        " rigid-body motion(s) free, and the loads pull the body off its "
        "obstacles along them (a mechanism: no equilibrium exists). Check "
        "the direction of the loads, the obstacles' normals and the "
        "supports. Results were written with converged = false.");
    if (has_contact && contact_solver.roundoff_limited)
      {
        std::ostringstream s;
        s << "the displacement augmented Lagrangian reached its round-off "
             "floor at multiplier update "
          << contact_solver.history.size() << ": the change of the reactions, "
          << contact_solver.final_norm_pbar
          << ", has reached the noise floor that the rounding of the "
             "displacements and the linear solver's tolerance leave at this "
             "stiffness (about "
          << contact_solver.roundoff_floor << "), above the tolerance "
          << contact_solver.tolerance_used
          << ". Loosen Augmented Lagrangian/Relative tolerance, reduce "
             "Initial penalty, or tighten Linear solver/Tolerance. Results "
             "were written with converged = false.";
        throw NotConvergedError(s.str());
      }
    if (has_contact && contact_solver.periodic)
      throw NotConvergedError(
        "the diagonal scheme cycles: multiplier update " +
        std::to_string(contact_solver.history.size()) +
        " reproduced an earlier update (the same branches, penalties and "
        "multipliers), so the iteration is periodic and would never converge. "
        "Take Augmented Lagrangian/Iteration scheme = classical, or another "
        "Initial penalty." +
        mechanism_hint() + " Results were written with converged = false.");
    if (has_contact && contact_solver.cycled)
      throw NotConvergedError(
        "the inner Newton iteration of multiplier update " +
        std::to_string(contact_solver.history.size() + 1) +
        " cycles: it came back to a released set it had already solved, so "
        "it would never reach its tolerance. " +
        std::string(
          contact_solver.regularisation ==
              AugmentedLagrangianSolver::Regularisation::macaulay ?
            "The Macaulay bracket (p)_+ has a kink at p = 0 wherever mu is "
            "not 0, so its pieces do not join with a continuous slope. Use the "
            "consistent augmented Lagrangian, or Iteration scheme = diagonal." :
            "The pieces join smoothly, so the solves have lost their digits: "
            "the usual cause is an Initial penalty far larger than the nodal "
            "compliance of the mesh (released springs that no longer hold the "
            "body). Reduce Augmented Lagrangian/Initial penalty.") +
        mechanism_hint() + " Results were written with converged = false.");
    if (has_contact && contact_solver.diverged)
      {
        std::ostringstream s;
        s << "the augmented Lagrangian iteration stopped at multiplier update "
          << contact_solver.history.size() << " without converging: ||pbar|| = "
          << contact_solver.final_norm_pbar
          << " either exceeds a million times the load scale or would need "
             "alpha beyond Maximum penalty growth x Initial penalty (alpha is "
          << contact_solver.alpha.front()
          << "). The usual cause is an Initial penalty far from the nodal "
             "compliance of the mesh: far larger, the released springs no "
             "longer hold the body and the solves lose their digits; far "
             "smaller, alpha cannot grow enough. Adjust Augmented "
             "Lagrangian/Initial penalty."
          << mechanism_hint()
          << " Results were written with converged = false.";
        throw NotConvergedError(s.str());
      }
    if (has_contact && !contact_solver.converged)
      {
        std::ostringstream s;
        s << "the augmented Lagrangian iteration did not converge in "
          << contact_solver.history.size()
          << " multiplier updates (Augmented Lagrangian/Maximum multiplier "
             "updates): ||pbar|| = "
          << contact_solver.final_norm_pbar << " > tolerance "
          << contact_solver.tolerance_used << ". Results were written with "
          << "converged = false.";
        throw NotConvergedError(s.str());
      }
  }

  template class HRProblem<2>;
  template class HRProblem<3>;
} // namespace hrcontact
