#include <deal.II/base/timer.h>

#include <hrcontact/adaptivity/adaptive_run.h>
#include <hrcontact/adaptivity/contact_zone_refinement.h>
#include <hrcontact/adaptivity/refinement_indicator.h>
#include <hrcontact/core/hr_problem.h>

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

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
        record.seconds       = timer.wall_time();
        record.linear_solves = r.solve.linear_statistics.solves;
        record.carried_start = r.contact && !r.contact->start_origin.empty() &&
                               r.coarse_levels.empty();
        refinement.cycles.push_back(record);
        log << "  adaptive cycle " << cycle << ": " << record.cells
            << " cells, " << record.displacement_dofs << " dofs, "
            << refinement.estimator << " estimate " << std::setprecision(4)
            << record.estimate << ", " << record.linear_solves
            << (record.linear_solves == 1 ? " linear solve" : " linear solves")
            << (record.carried_start ? " from the previous cycle's state" : "")
            << ", " << std::setprecision(3) << record.seconds << " s"
            << std::endl;
        const bool last = last_possible ||
                          (refinement.maximum_dofs > 0 &&
                           record.displacement_dofs >= refinement.maximum_dofs);
        if (last)
          {
            problem.refine_adaptively(refinement);
            if (!last_possible)
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
