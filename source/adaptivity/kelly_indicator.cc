#include <deal.II/base/quadrature_lib.h>

#include <deal.II/numerics/error_estimator.h>

#include <hrcontact/adaptivity/kelly_indicator.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  KellyIndicator<dim>::estimate(const Results<dim> &results,
                                Vector<float>      &indicators) const
  {
    indicators.reinit(results.triangulation().n_active_cells());
    KellyErrorEstimator<dim>::estimate(results.spaces.dof_handler_displacement,
                                       QGauss<dim - 1>(2),
                                       {},
                                       results.displacement,
                                       indicators);
  }

  template class KellyIndicator<2>;
  template class KellyIndicator<3>;

  HRCONTACT_REGISTER_REFINEMENT_INDICATOR(
    KellyIndicator,
    "kelly",
    "the jump of the displacement gradient across faces (deal.II's "
    "KellyErrorEstimator, as step-42)")
} // namespace hrcontact
