#ifndef hrcontact_contact_tables_h
#define hrcontact_contact_tables_h

#include <hrcontact/postprocess/postprocessor.h>

#include <string>

namespace hrcontact
{
  /**
   * Postprocessor "contact tables" (scenes with contact): contact.csv (one
   * row per unilateral constraint), stops.csv (one row per two-sided stop),
   * history.csv (one row per multiplier update) and, for the Tracked contact
   * nodes, contact-history.csv.
   */
  template <int dim>
  class ContactTables : public Postprocessor<dim>
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
    std::string tracked_nodes;
  };
} // namespace hrcontact

#endif
