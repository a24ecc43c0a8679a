#ifndef hrcontact_bound_indicator_h
#define hrcontact_bound_indicator_h

#include <hrcontact/adaptivity/refinement_indicator.h>

namespace hrcontact
{
  /**
   * `Estimator = bound`: each cell's share eta_K of the guaranteed bound
   * eta = |tau - C eps(u_h)|_{C^-1} >= |u - u_h|_E (EquilibratedStress,
   * doc/error-bounds.md). Unlike the other indicators its sum is an upper
   * bound of the error itself, so it also serves Mesh refinement/Target
   * error. Covers what EquilibratedStress covers (2D, linear elastic and
   * Ramberg-Osgood bodies,
   * straight obstacles); other scenes are refused by name before the first
   * solve.
   */
  template <int dim>
  class BoundIndicator : public RefinementIndicator<dim>
  {
  public:
    void
    estimate(const Results<dim>    &results,
             dealii::Vector<float> &indicators) const override;

    void
    check(const Scene<dim> &scene) const override;

    std::optional<double>
    relative_bound() const override
    {
      return last_relative_bound;
    }

  private:
    /** eta / |sigma_h|_{C^-1} of the last estimate. */
    mutable std::optional<double> last_relative_bound;
  };
} // namespace hrcontact

#endif
