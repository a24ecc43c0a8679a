#include <hrcontact/adaptivity/bound_indicator.h>
#include <hrcontact/adaptivity/equilibrated_stress.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  BoundIndicator<dim>::check(const Scene<dim> &scene) const
  {
    EquilibratedStress<dim>::check_scene(scene);
  }

  template <int dim>
  void
  BoundIndicator<dim>::estimate(const Results<dim> &results,
                                Vector<float>      &indicators) const
  {
    EquilibratedStress<dim> tau(results);
    tau.compute();
    const auto &eta_squared = tau.cell_bound_squared();
    indicators.reinit(eta_squared.size());
    for (unsigned int k = 0; k < indicators.size(); ++k)
      indicators[k] = std::sqrt(eta_squared[k]);
    const double energy = std::sqrt(tau.solution_energy_squared());
    last_relative_bound = energy > 0 ? tau.bound() / energy : tau.bound();
  }

  template class BoundIndicator<2>;
  template class BoundIndicator<3>;

  HRCONTACT_REGISTER_REFINEMENT_INDICATOR(
    BoundIndicator,
    "bound",
    "each cell's share of the guaranteed error bound (the Prager-Synge "
    "distance of an equilibrated stress to C eps(u_h), doc/error-bounds.md; "
    "2D, linear elastic and Ramberg-Osgood bodies, contact with straight "
    "obstacles)")
} // namespace hrcontact
