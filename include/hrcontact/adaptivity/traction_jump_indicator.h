#ifndef hrcontact_traction_jump_indicator_h
#define hrcontact_traction_jump_indicator_h

#include <hrcontact/adaptivity/refinement_indicator.h>

namespace hrcontact
{
  /**
   * `Estimator = traction jump`: what only a stress formulation has. The
   * discontinuous stresses' normal traction jumps across a face where the
   * discrete equilibrium is weak; the exact stresses have none (and meet
   * the applied traction on a loaded or free boundary). Per cell
   *
   *   eta_K^2 = sum over its faces f of h_f / 2 int_f |[sigma n]|^2
   *           + sum over its free or loaded boundary faces h_f int_f
   *             |sigma n - t|^2,
   *
   * the face terms of a residual estimator in stresses, halved between the
   * two cells of an interior face. A face between a coarse cell and its
   * finer neighbours is integrated on each small face. Supported and
   * contact boundaries have unknown tractions and add nothing.
   */
  template <int dim>
  class TractionJumpIndicator : public RefinementIndicator<dim>
  {
  public:
    void
    estimate(const Results<dim>    &results,
             dealii::Vector<float> &indicators) const override;
  };
} // namespace hrcontact

#endif
