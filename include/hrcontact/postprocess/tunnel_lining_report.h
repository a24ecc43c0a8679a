#ifndef hrcontact_tunnel_lining_report_h
#define hrcontact_tunnel_lining_report_h

#include <hrcontact/postprocess/postprocessor.h>

#include <string>

namespace hrcontact
{
  /**
   * Postprocessor "tunnel lining" (tunnel_lining grids, 2D): section forces
   * N, V, M along the mid-line (lining.csv), extremes of N, M and of the
   * principal stresses in summary.txt, and with contact the pressure along
   * the extrados (lining-contact.csv) and the pressed zones.
   */
  template <int dim>
  class TunnelLiningReport : public Postprocessor<dim>
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
    /** The section forces walk along lines across the lining's cells. */
    bool
    needs_replicated_mesh(const Scene<dim> &scene) const override;

  private:
    unsigned int n_sections = 120;
    std::string  reference_principal_stresses;
  };
} // namespace hrcontact

#endif
