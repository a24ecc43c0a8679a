#include <deal.II/base/timer.h>

#include <hrcontact/adaptivity/adaptive_run.h>
#include <hrcontact/adaptivity/bound_indicator.h>
#include <hrcontact/adaptivity/contact_zone_refinement.h>
#include <hrcontact/adaptivity/equilibrated_stress.h>
#include <hrcontact/adaptivity/refinement_indicator.h>
#include <hrcontact/core/hr_problem.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** The guaranteed relative error bound of a cycle: the estimator's, or
     * for a Target error one computed beside it; -1 when neither. */
    template <int dim>
    double
    relative_bound(const RefinementIndicator<dim> &estimator,
                   const AdaptiveRefinement<dim>  &refinement,
                   const Results<dim>             &r)
    {
      if (const auto bound = estimator.relative_bound())
        return *bound;
      if (refinement.target_error <= 0)
        return -1;
      BoundIndicator<dim> bound;
      Vector<float>       indicators;
      bound.estimate(r, indicators);
      return *bound.relative_bound();
    }
  } // namespace

  template <int dim>
  AdaptiveRefinement<dim>
  run_adaptive_cycles(ParameterHandler &prm,
                      std::ostream     &log,
                      const MPI_Comm    communicator,
                      Summary          *summary)
  {
    AdaptiveRefinement<dim> refinement;
    refinement.parse_parameters(prm);
    ContactZoneRefinement<dim> contact_zone;
    contact_zone.parse_parameters(prm);
    const auto estimator =
      RefinementIndicatorFactory<dim>::create(refinement.estimator);
    // The previous cycle's problem lives on until the next has carried its
    // state.
    std::unique_ptr<HRProblem<dim>> previous;
    for (unsigned int cycle = 0;; ++cycle)
      {
        Timer timer;
        auto  current = std::make_unique<HRProblem<dim>>(prm, communicator);
        HRProblem<dim> &problem = *current;
        if (cycle == 0)
          {
            // Refused before any solve.
            estimator->check(problem.results().scene);
            if (refinement.target_error > 0)
              EquilibratedStress<dim>::check_scene(problem.results().scene);
            // The 3D bound needs conforming meshes; the cycles' refinement
            // makes hanging nodes.
            if (dim == 3 && refinement.n_cycles > 0 &&
                (refinement.estimator == "bound" ||
                 refinement.target_error > 0))
              throw InputError(
                "Mesh refinement: the error bound (Estimator = bound, "
                "Target error) covers conforming meshes only in 3D so far, "
                "and adaptive cycles make hanging nodes; refine uniformly "
                "(Geometry/Global refinements) and use Postprocess/Error "
                "bound.");
          }
        problem.refine_adaptively(refinement,
                                  refinement.carry_state ? previous.get() :
                                                           nullptr);
        std::ostringstream cycle_log;
        const bool         last_possible = cycle == refinement.n_cycles;
        // The last cycle speaks as a run without cycles does.
        problem.solve(last_possible ? log : cycle_log);
        const Results<dim> &r = problem.results();
        Vector<float>       indicators;
        estimator->estimate(r, indicators);
        AdaptiveCycle record;
        record.cells             = r.triangulation().n_global_active_cells();
        record.displacement_dofs = r.system.n_displacement_dofs;
        record.estimate          = std::sqrt(
          Utilities::MPI::sum(indicators.norm_sqr(), r.partition.communicator));
        // The bound of a Target error beside another estimator is part of
        // the cycle's time, as it is when the bound is the estimator.
        record.relative_bound = relative_bound(*estimator, refinement, r);
        record.seconds        = timer.wall_time();
        record.linear_solves  = r.solve.linear_statistics.solves;
        record.carried_start  = r.contact && !r.contact->start_origin.empty() &&
                               r.coarse_levels.empty();
        refinement.cycles.push_back(record);
        log << "  adaptive cycle " << cycle << ": " << record.cells
            << " cells, " << record.displacement_dofs << " dofs, "
            << refinement.estimator << " estimate " << std::setprecision(4)
            << record.estimate << ", " << record.linear_solves
            << (record.linear_solves == 1 ? " linear solve" : " linear solves")
            << (record.carried_start ? " from the previous cycle's state" : "");
        if (record.relative_bound >= 0)
          log << ", error bound " << std::setprecision(3)
              << 100 * record.relative_bound << " %";
        log << ", " << std::setprecision(3) << record.seconds << " s"
            << std::endl;
        const bool reached = refinement.target_error > 0 &&
                             record.relative_bound <= refinement.target_error;
        const bool most_dofs =
          refinement.maximum_dofs > 0 &&
          record.displacement_dofs >= refinement.maximum_dofs;
        if (last_possible || most_dofs || reached)
          {
            problem.refine_adaptively(refinement);
            if (reached)
              log << "  (Target error " << 100 * refinement.target_error
                  << " % reached: the energy error is at most "
                  << 100 * record.relative_bound << " %)" << std::endl;
            else if (refinement.target_error > 0)
              log << "  (Target error " << 100 * refinement.target_error
                  << " % NOT reached: the bound is "
                  << 100 * record.relative_bound << " % after " << cycle
                  << (most_dofs ? " cycles at Maximum dofs)" :
                                  " cycles, the most Adaptive cycles allows)")
                  << std::endl;
            else if (!last_possible)
              log << "  (Maximum dofs reached: no further cycle)" << std::endl;
            problem.output_results(log);
            if (!r.converged())
              throw NotConvergedError(problem.outcome_message());
            if (summary)
              *summary = r.summary;
            return refinement;
          }
        if (!r.converged())
          throw NotConvergedError("adaptive cycle " + std::to_string(cycle) +
                                  ": " + problem.outcome_message());
        refinement.history.push_back(refinement.mark(r.triangulation(),
                                                     indicators,
                                                     r.partition.communicator));
        if (const unsigned int added =
              contact_zone.add_to(r, refinement.history.back()))
          log << "    contact zone depth: " << added << " more"
              << (added == 1 ? " cell" : " cells")
              << " refined beneath the pressed zone" << std::endl;
        previous = std::move(current);
      }
  }

  template AdaptiveRefinement<2>
  run_adaptive_cycles<2>(ParameterHandler &,
                         std::ostream &,
                         const MPI_Comm,
                         Summary *);
  template AdaptiveRefinement<3>
  run_adaptive_cycles<3>(ParameterHandler &,
                         std::ostream &,
                         const MPI_Comm,
                         Summary *);
} // namespace hrcontact
