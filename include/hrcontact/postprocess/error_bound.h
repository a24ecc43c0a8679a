#ifndef hrcontact_error_bound_h
#define hrcontact_error_bound_h

#include <deal.II/base/function.h>

#include <hrcontact/postprocess/postprocessor.h>

#include <memory>

namespace hrcontact
{
  /**
   * Postprocessor "error bound" (Postprocess/Error bound = true): the
   * guaranteed bound eta >= |u - u_h|_E of the Prager-Synge identity from an
   * equilibrated stress (EquilibratedStress, doc/error-bounds.md), with how
   * exactly that stress is admissible; against a Postprocess/Reference stress
   * also the true energy error, the effectivity index eta / |u - u_h|_E and
   * the identity's defect.
   */
  template <int dim>
  class ErrorBound : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const Constants          &constants) override;
    std::string
    skip_reason(const Results<dim> &results) const override;
    /** A scene or rows the bound does not cover yet, refused before the
     * solve. */
    void
    check_input(const Scene<dim>                 &scene,
                const dealii::Triangulation<dim> &triangulation,
                const EquilibriumSystem          &system) const override;
    void
    execute(const Results<dim> &results, PostprocessOutput &output) override;

  private:
    bool compute = false;
    /** Its input is checked before the solve: it computes the bound, or
     * bound-driven adaptive cycles do. */
    bool                                   check = false;
    std::unique_ptr<dealii::Function<dim>> reference_stress;
  };
} // namespace hrcontact

#endif
