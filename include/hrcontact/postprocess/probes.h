#ifndef hrcontact_probes_h
#define hrcontact_probes_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/postprocess/postprocessor.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  /**
   * Postprocessor "probes": quantities at points (probe.NAME), compared with
   * reference values (reference.NAME, relative_error.NAME), and the error
   * against a reference stress field (stress_error_max, stress_error_l2).
   */
  template <int dim>
  class Probes : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants) override;
    void
    execute(const Results<dim> &results, PostprocessOutput &output) override;
    /** Every probe point inside the body, before the solve. */
    void
    check_input(const Scene<dim>                 &scene,
                const dealii::Triangulation<dim> &triangulation,
                const EquilibriumSystem          &system) const override;

  private:
    struct Probe
    {
      std::string        name;
      dealii::Point<dim> point;
      std::string        quantity;
    };
    std::vector<Probe>                           probes;
    std::vector<std::pair<std::string, double>>  reference_values;
    std::unique_ptr<dealii::FunctionParser<dim>> reference_stress;
  };
} // namespace hrcontact

#endif
