#ifndef hrcontact_contact_pressure_h
#define hrcontact_contact_pressure_h

#include <hrcontact/postprocess/postprocessor.h>
#include <hrcontact/postprocess/pressure_plot.h>

#include <string>

namespace hrcontact
{
  /**
   * Postprocessor "contact pressure" (2D contact, not tunnel linings): nodal
   * pressures from the reactions over their tributary lengths, the peak
   * pressure and the contact zone, and with Hertz load and radius given the
   * comparison with plane-strain Hertz contact of a cylinder on a rigid
   * plane (linear isotropic material).
   */
  template <int dim>
  class ContactPressure : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants) override;
    std::string
    skip_reason(const Results<dim> &results) const override;
    void
    execute(const Results<dim> &results, PostprocessOutput &output) override;

  private:
    /** Hertz's half width and peak pressure (a = 0 without Hertz load and
     * radius). */
    HertzEllipse
    hertz_ellipse(const Results<dim> &results) const;

    std::string hertz_load, hertz_radius, hertz_modulus;
    /** Postprocess/Pressure plot. */
    bool plot = false;
  };
} // namespace hrcontact

#endif
