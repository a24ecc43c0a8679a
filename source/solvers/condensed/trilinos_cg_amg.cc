#include <deal.II/base/timer.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/trilinos_cg_amg.h>

#include <sstream>

#include <Epetra_MultiVector.h>

namespace hrcontact
{
  using namespace dealii;

  struct TrilinosCgAmg::AtSetupValues
  {
    TrilinosCgAmg &d;
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const
    {
      d.swap_row_values(d.setup_values);
      d.preconditioner.vmult(dst, src);
      d.swap_row_values(d.setup_values);
    }
  };

  TrilinosCgAmg::TrilinosCgAmg(const EquilibriumSystem    &system,
                               const LinearSolverSettings &settings,
                               const DofPartition         &partition,
                               const bool                  ghosted_u,
                               LinearSolverStatistics     &statistics)
    : TrilinosBackEnd(system, settings, partition, ghosted_u, statistics)
    , cg_tolerance(settings.tolerance)
  {
    statistics.tolerance = cg_tolerance;
  }

  TrilinosCgAmg::~TrilinosCgAmg() = default;

  void
  TrilinosCgAmg::set_start(const FieldVector &u_start)
  {
    if (!settings.warm_start)
      return;
    for (const auto i : partition.owned)
      x[i] = u_start(i);
    x.compress(VectorOperation::insert);
  }

  bool
  TrilinosCgAmg::tighten()
  {
    // Below 1e-15 of the right-hand side CG stagnates in double precision.
    constexpr double floor = 1e-15;
    if (cg_tolerance <= floor)
      return false;
    cg_tolerance         = std::max(floor, 1e-2 * cg_tolerance);
    statistics.tolerance = cg_tolerance;
    ++statistics.tightenings;
    return true;
  }

  void
  TrilinosCgAmg::matrix_changing()
  {
    // A new matrix needs a new hierarchy, unless the settings keep one
    // across steps.
    if (!settings.reuses_preconditioner(system.dim))
      built = false;
  }

  void
  TrilinosCgAmg::drop_matrix_dependents()
  {
    preconditioner.clear();
    built = false;
  }

  double
  TrilinosCgAmg::build_preconditioner()
  {
    Timer setup_timer;
    preconditioner.clear();
    // ML keeps a pointer to the matrix: a hierarchy that outlives the
    // step keeps the values of the rows the steps change.
    if (settings.reuses_preconditioner(system.dim))
      setup_values = row_values();
    const TrilinosWrappers::SparseMatrix &M = matrix;
    // Smoothed aggregation for an elliptic operator; the near null space
    // is the rigid-body modes (ML's pre-computed null space), since the
    // translations alone (deal.II 9.4's constant modes) coarsen bending
    // poorly.
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = settings.smoother_sweeps;
    data.aggregation_threshold = settings.aggregation_threshold;
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(list, unused, M);
    const unsigned int dim     = system.dim;
    const unsigned int n_modes = (dim == 2) ? 3 : 6;
    const auto        &map     = M.trilinos_matrix().DomainMap();
    modes = std::make_unique<Epetra_MultiVector>(map, n_modes);
    for (int k = 0; k < map.NumMyElements(); ++k)
      {
        const auto         i   = TrilinosWrappers::global_index(map, k);
        const unsigned int c   = system.dof_component(i);
        const auto        &xyz = system.node_coordinates[system.dof_node(i)];
        for (unsigned int m = 0; m < n_modes; ++m)
          (*modes)[m][k] = 0;
        (*modes)[c][k] = 1; // translations
        // Rotations about the axes: (-y, x, 0), (0, -z, y), (z, 0, -x).
        if (dim == 2)
          (*modes)[2][k] = (c == 0) ? -xyz[1] : xyz[0];
        else
          {
            (*modes)[3][k] = (c == 0) ? -xyz[1] : (c == 1) ? xyz[0] : 0.;
            (*modes)[4][k] = (c == 1) ? -xyz[2] : (c == 2) ? xyz[1] : 0.;
            (*modes)[5][k] = (c == 2) ? -xyz[0] : (c == 0) ? xyz[2] : 0.;
          }
      }
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", static_cast<int>(n_modes));
    list.set("null space: vectors", modes->Values());
    list.set("null space: add default vectors", false);
    statistics.aggregation =
      settings.aggregates_by_coordinates() ? "coordinates" : "matrix";
    if (settings.aggregates_by_coordinates())
      {
        // ML's auxiliary aggregation reads one coordinate per node, the
        // nodes' dofs numbered together (dim n + d, on one process).
        for (auto &c : node_xyz)
          c.clear();
        for (int k = 0; k < map.NumMyElements(); ++k)
          {
            const auto i = TrilinosWrappers::global_index(map, k);
            AssertThrow(system.dof_component(i) == k % dim,
                        ExcMessage("coordinate aggregation needs each "
                                   "node's dofs together on one process"));
            if (k % dim == 0)
              for (unsigned int c = 0; c < dim; ++c)
                node_xyz[c].push_back(
                  system.node_coordinates[system.dof_node(i)][c]);
          }
        const char *axis[3] = {"x-coordinates",
                               "y-coordinates",
                               "z-coordinates"};
        for (unsigned int c = 0; c < dim; ++c)
          list.set(axis[c], node_xyz[c].data());
        list.set("PDE equations", static_cast<int>(dim));
        list.set("aggregation: aux: enable", true);
        list.set("aggregation: aux: threshold", settings.coordinate_threshold);
      }
    preconditioner.initialize(M, list);
    built = true;
    ++statistics.preconditioner_setups;
    return setup_timer.wall_time();
  }

  std::pair<bool, unsigned int>
  TrilinosCgAmg::run_cg(const double tolerance)
  {
    SolverControl control(settings.max_iterations, tolerance, false, false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        if (settings.reuses_preconditioner(system.dim))
          cg.solve(matrix, x, rhs, AtSetupValues{*this});
        else
          cg.solve(matrix, x, rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &)
      {
        statistics.iterations += control.last_step();
        return std::make_pair(false, control.last_step());
      }
    statistics.iterations += control.last_step();
    return std::make_pair(true, control.last_step());
  }

  void
  TrilinosCgAmg::solve_assembled()
  {
    Timer timer;
    // The AMG set-ups' share, counted as set-up and not as solve.
    double setup_seconds = 0;
    bool   fresh         = false;
    if (!built)
      {
        setup_seconds += build_preconditioner();
        fresh = true;
      }
    // CG stops at cg_tolerance of the right-hand side, as from a zero start;
    // a warm start whose residual is already near that (a multiplier update
    // that moves a few rows) must still resolve its change, or p would not
    // move and the multipliers would stall (the bridge with stops took 16
    // updates instead of 6): then it stops at Warm start reduction of its
    // initial residual, but not below 1e-15 of the right-hand side.
    const double rhs_norm  = rhs.l2_norm();
    double       tolerance = cg_tolerance * rhs_norm;
    if (settings.warm_start)
      {
        TrilinosWrappers::MPI::Vector r0(rhs);
        matrix.vmult(r0, x);
        r0.sadd(-1., rhs);
        tolerance =
          std::max(std::min(tolerance,
                            settings.warm_start_reduction * r0.l2_norm()),
                   std::min(tolerance, 1e-15 * rhs_norm));
      }
    auto [converged, steps] = run_cg(tolerance);
    if (!converged && !fresh)
      {
        // A hierarchy from an earlier Newton step no longer serves: rebuild.
        setup_seconds += build_preconditioner();
        fresh                      = true;
        std::tie(converged, steps) = run_cg(tolerance);
      }
    if (!converged)
      {
        std::ostringstream what;
        what << "Condensed path: CG with AMG did not reach ";
        if (statistics.tightenings > 0)
          what << "the tolerance " << cg_tolerance
               << " (Linear solver/Tolerance, tightened after an inner "
                  "Newton cycle)";
        else
          what << "Linear solver/Tolerance";
        what << " in Linear solver/Maximum iterations = "
             << settings.max_iterations
             << " iterations. Raise the limit, loosen the tolerance, or take "
                "Linear solver/Solver = direct.";
        throw NotConvergedError(what.str());
      }
    if (statistics.solves == 1)
      statistics.first_solve_iterations = statistics.iterations;
    if (fresh)
      iterations_after_setup = steps;
    else if (steps > 2 * iterations_after_setup + 5)
      built = false; // rebuild before the next solve
    statistics.setup_seconds += setup_seconds;
    statistics.solve_seconds += timer.wall_time() - setup_seconds;
  }
} // namespace hrcontact
