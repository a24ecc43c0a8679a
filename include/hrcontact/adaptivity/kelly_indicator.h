#ifndef hrcontact_kelly_indicator_h
#define hrcontact_kelly_indicator_h

#include <hrcontact/adaptivity/refinement_indicator.h>

namespace hrcontact
{
  /**
   * `Estimator = kelly`: deal.II's KellyErrorEstimator on the displacements,
   * the jump of their gradient across faces (as step-42 refines), the
   * baseline a displacement code has too.
   */
  template <int dim>
  class KellyIndicator : public RefinementIndicator<dim>
  {
  public:
    void
    estimate(const Results<dim>    &results,
             dealii::Vector<float> &indicators) const override;
  };
} // namespace hrcontact

#endif
