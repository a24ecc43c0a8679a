#ifndef hrcontact_balance_report_h
#define hrcontact_balance_report_h

#include <hrcontact/postprocess/postprocessor.h>

namespace hrcontact
{
  /**
   * Postprocessor "balance": the global balance of loads and reactions
   * (total_load_*, total_reaction_*, equilibrium_imbalance), with contact the
   * Signorini conditions of eq. 12 on the unilateral rows and which branch
   * each two-sided stop sits on, and the largest displacement component.
   */
  template <int dim>
  class BalanceReport : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &)
    {}
    void
    execute(const Results<dim> &results, PostprocessOutput &output) override;
  };
} // namespace hrcontact

#endif
