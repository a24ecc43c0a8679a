#ifndef hrcontact_contact_residual_indicator_h
#define hrcontact_contact_residual_indicator_h

#include <hrcontact/adaptivity/refinement_indicator.h>

namespace hrcontact
{
  /**
   * `Estimator = contact residual`: the traction jump indicator, made an
   * energy by the compliance c = (e e) : C^{-1} (e e) of the material at
   * zero stress, plus what the contact faces say, which the traction jump
   * leaves out (their tractions are unknown to it):
   *
   *   eta_K^2 = c eta_jump,K^2
   *           + sum over K's contact faces f of
   *               c h_f int_f |sigma n + p_h n|^2
   *             + 2 int_f |p_h (g - u_n)_h|.
   *
   * p_h and (g - u_n)_h interpolate the nodal contact pressures and gaps
   * (ContactFields). The first contact term is the misfit of the
   * discontinuous stresses' traction to the frictionless nodal pressure
   * (no tangential traction); the second is the complementarity term of
   * the Prager-Synge bound (issue 52's inequality). Both vanish for the
   * exact solution. The complementarity term is nonzero only on the faces
   * where a pressed node meets an open one: the edge of the contact zone,
   * where the pressure's square root lives and which the energy
   * indicators hardly see.
   */
  template <int dim>
  class ContactResidualIndicator : public RefinementIndicator<dim>
  {
  public:
    void
    estimate(const Results<dim>    &results,
             dealii::Vector<float> &indicators) const override;
  };
} // namespace hrcontact

#endif
