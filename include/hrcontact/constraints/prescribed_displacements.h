#ifndef hrcontact_prescribed_displacements_h
#define hrcontact_prescribed_displacements_h

#include <deal.II/base/function_parser.h>

#include <hrcontact/constraints/constraint_source.h>

#include <map>
#include <memory>

namespace hrcontact
{
  /**
   * Supports/Prescribed displacements: displacement components fixed on
   * the nodes of a boundary, the H rows of eq. 38 (reactions r = H s -
   * f_H). Where two boundaries meet, their values must agree.
   */
  template <int dim>
  class PrescribedDisplacements : public ConstraintSource<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    bool
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants,
                     const std::vector<std::shared_ptr<ConstraintSource<dim>>>
                       &earlier) override;
    std::string
    entry() const override;
    bool
    acts_on(const dealii::types::boundary_id id) const override;
    std::vector<dealii::types::boundary_id>
    boundary_ids() const override;
    bool
    is_normal_kind() const override;
    double
    prescribed_value(const dealii::types::boundary_id id,
                     const unsigned int               d,
                     const dealii::Point<dim>        &x) const override;
    void
    collect(const BoundaryFace<dim> &face,
            const EquilibriumSystem &system,
            NodeConstraintMap<dim>  &nodes) const override;

  private:
    struct Prescription
    {
      std::vector<unsigned int>                    components;
      std::unique_ptr<dealii::FunctionParser<dim>> values; // one per component
    };
    std::map<dealii::types::boundary_id, Prescription> prescriptions;
  };
} // namespace hrcontact

#endif
