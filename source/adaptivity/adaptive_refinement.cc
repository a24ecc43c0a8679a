#include <deal.II/base/utilities.h>

#include <hrcontact/adaptivity/adaptive_refinement.h>
#include <hrcontact/adaptivity/contact_zone_refinement.h>
#include <hrcontact/adaptivity/refinement_indicator.h>
#include <hrcontact/core/input.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  AdaptiveRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry(
        "Adaptive cycles",
        "0",
        Patterns::Integer(0, 30),
        "How many times the solved mesh is refined where the Estimator "
        "says, and solved again (0: the mesh as the Geometry and the "
        "Refinement region give it). Only the last cycle writes results; "
        "summary.txt lists every cycle's cells, dofs, time and estimate.");
      prm.declare_entry("Estimator",
                        "kelly",
                        Patterns::Anything(),
                        "Where to refine: " +
                          RefinementIndicatorFactory<dim>::descriptions() +
                          ". Each cell's indicator goes to solution.vtu "
                          "(refinement_indicator).");
      prm.declare_entry(
        "Marking",
        "fixed number",
        Patterns::Selection("fixed number|fixed fraction"),
        "What the fractions count. fixed number: cells (step-42's "
        "refine_and_coarsen_fixed_number: the mesh grows by about the same "
        "factor each cycle, wherever the error is). fixed fraction: the "
        "squared estimate (Doerfler's bulk marking: the fewest cells that "
        "carry Refine fraction of the sum of squared indicators are refined, "
        "the most that carry Coarsen fraction of it coarsened), so a "
        "concentrated error refines few cells.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(),
                        "The fraction of all cells (Marking = fixed number) "
                        "or of the squared estimate (fixed fraction), those "
                        "with the largest indicators, refined in each cycle "
                        "(in [0, 1]).");
      prm.declare_entry("Coarsen fraction",
                        "0.03",
                        Patterns::Double(),
                        "The fraction of all cells (or of the squared "
                        "estimate), those with the smallest indicators, "
                        "coarsened in each cycle (in [0, 1]; never below the "
                        "global refinements).");
      prm.declare_entry(
        "Carry state",
        "true",
        Patterns::Bool(),
        "Each cycle's contact iteration starts from the previous cycle's "
        "pressed set, multipliers and penalties, carried to the new mesh by "
        "position (pressures per tributary length), and CG from its "
        "displacements, instead of from the trial solution and coarser "
        "levels of its own. The answer is the same to the tolerance; Hertz "
        "from 4 refinements: 2 linear solves per cycle instead of 2-3 after "
        "about 30 on coarser levels (doc/adaptivity.md). false: every cycle "
        "from the start (for comparison).");
      prm.declare_entry(
        "Target error",
        "0",
        Patterns::Double(0, 1),
        "Stop the cycles once the guaranteed bound of the energy error "
        "(doc/error-bounds.md), relative to the energy norm of the computed "
        "stresses, is at or below this (0.01: 1 %; 0: no target, all "
        "Adaptive cycles run). Adaptive cycles is then the most cycles "
        "tried; a run that ends above the target says so in the log and in "
        "summary.txt (target_error_reached = 0). The bound covers 2D linear "
        "elastic and Ramberg-Osgood bodies, contact with straight obstacles "
        "included, so far; "
        "it is computed each cycle "
        "(with Estimator = bound, once for both).");
      prm.declare_entry("Maximum dofs",
                        "0",
                        Patterns::Integer(0),
                        "No further cycle once a mesh has this many "
                        "displacement dofs (0: no ceiling).");
    }
    prm.leave_subsection();
    ContactZoneRefinement<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  AdaptiveRefinement<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    n_cycles         = prm.get_integer("Adaptive cycles");
    estimator        = Utilities::trim(prm.get("Estimator"));
    refine_fraction  = prm.get_double("Refine fraction");
    coarsen_fraction = prm.get_double("Coarsen fraction");
    fixed_fraction =
      get_selection<bool>(prm,
                          "Marking",
                          {{"fixed number", false}, {"fixed fraction", true}});
    maximum_dofs = prm.get_integer("Maximum dofs");
    target_error = prm.get_double("Target error");
    carry_state  = prm.get_bool("Carry state");
    prm.leave_subsection();
    const std::string where = "Mesh refinement/";
    for (const auto &[name, value] :
         {std::make_pair("Refine fraction", refine_fraction),
          std::make_pair("Coarsen fraction", coarsen_fraction)})
      if (!(value >= 0 && value <= 1))
        throw InputError(where + name + " = " + std::to_string(value) +
                         ": a fraction of the cells lies in [0, 1].");
    if (refine_fraction + coarsen_fraction > 1)
      throw InputError(where + "Refine fraction + Coarsen fraction = " +
                       std::to_string(refine_fraction + coarsen_fraction) +
                       " exceeds 1: a cell cannot be refined and coarsened.");
    // The name is checked now, not after the first solve.
    RefinementIndicatorFactory<dim>::create(estimator);
    history.clear();
    cycles.clear();
  }

  template <int dim>
  void
  AdaptiveRefinement<dim>::apply(Triangulation<dim> &triangulation,
                                 const unsigned int  coarsest_level) const
  {
    for (const RefinementStep &step : history)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const std::string id = cell->id().to_string();
              if (step.refine.count(id) > 0)
                cell->set_refine_flag();
              else if (step.coarsen.count(id) > 0 &&
                       cell->level() > int(coarsest_level))
                cell->set_coarsen_flag();
            }
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template <int dim>
  RefinementStep
  AdaptiveRefinement<dim>::mark(const Triangulation<dim> &triangulation,
                                const Vector<float>      &indicators,
                                const MPI_Comm            communicator) const
  {
    std::vector<float> own;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        own.push_back(indicators[cell->active_cell_index()]);
    std::vector<float> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, own))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), std::greater<float>());
    const std::size_t n         = all.size();
    std::size_t       n_refine  = std::size_t(refine_fraction * n);
    std::size_t       n_coarsen = std::size_t(coarsen_fraction * n);
    if (fixed_fraction)
      {
        // Doerfler: the largest indicators until their squares reach the
        // fraction of the total; the smallest up to theirs.
        double total = 0;
        for (const float eta : all)
          total += double(eta) * eta;
        double sum = 0;
        for (n_refine = 0; n_refine < n && sum < refine_fraction * total;
             ++n_refine)
          sum += double(all[n_refine]) * all[n_refine];
        sum = 0;
        for (n_coarsen = 0; n_coarsen < n - n_refine; ++n_coarsen)
          {
            const double eta = all[n - 1 - n_coarsen];
            if (sum + eta * eta > coarsen_fraction * total)
              break;
            sum += eta * eta;
          }
      }
    // Refine the cells at or above the n_refine-th largest indicator,
    // coarsen those at or below the n_coarsen-th smallest.
    const float refine_above =
      n_refine > 0 ? all[n_refine - 1] : std::numeric_limits<float>::max();
    const float coarsen_below = n_coarsen > 0 ? all[n - n_coarsen] : -1.f;
    std::vector<std::string> refine, coarsen;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const float eta = indicators[cell->active_cell_index()];
          if (n_refine > 0 && eta >= refine_above && eta > 0)
            refine.push_back(cell->id().to_string());
          else if (n_coarsen > 0 && eta <= coarsen_below)
            coarsen.push_back(cell->id().to_string());
        }
    RefinementStep step;
    for (const auto &part : Utilities::MPI::all_gather(communicator, refine))
      step.refine.insert(part.begin(), part.end());
    for (const auto &part : Utilities::MPI::all_gather(communicator, coarsen))
      step.coarsen.insert(part.begin(), part.end());
    return step;
  }

  template class AdaptiveRefinement<2>;
  template class AdaptiveRefinement<3>;
} // namespace hrcontact
