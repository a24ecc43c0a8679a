#ifndef hrcontact_solution_output_h
#define hrcontact_solution_output_h

#include <deal.II/base/data_out_base.h>

#include <hrcontact/postprocess/postprocessor.h>

namespace hrcontact
{
  /**
   * Postprocessor "solution": solution.vtu for ParaView (displacement,
   * stress tensor, principal stresses, von Mises, the stress components,
   * and with contact the nodal contact_pressure, contact_gap and
   * contact_status of ContactFields),
   * or under mpirun solution.pvtu with one piece solution_NNNN.vtu per
   * process and a "subdomain" field. Output/Write solution switches it off.
   */
  template <int dim>
  class SolutionOutput : public Postprocessor<dim>
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
    bool write = true;
    /** Output/Solution compression. */
    dealii::DataOutBase::VtkFlags::ZlibCompressionLevel compression =
      dealii::DataOutBase::VtkFlags::best_speed;
  };
} // namespace hrcontact

#endif
