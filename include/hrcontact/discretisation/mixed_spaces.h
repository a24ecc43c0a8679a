#ifndef hrcontact_mixed_spaces_h
#define hrcontact_mixed_spaces_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <string>

namespace hrcontact
{
  /**
   * The two discrete spaces of the Hellinger-Reissner discretisation (eq. 30):
   * continuous Q1 displacements and discontinuous stresses, one scalar DG
   * element per independent component of the symmetric tensor. Stress dofs
   * never couple across cells, so the flexibility F is block diagonal.
   */
  template <int dim>
  class MixedSpaces
  {
  public:
    static constexpr unsigned int n_stress_components = dim * (dim + 1) / 2;

    MixedSpaces();

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Create the elements and distribute dofs on the given mesh. */
    void
    setup(const dealii::Triangulation<dim> &triangulation);

    /**
     * Index pair (a, b), a <= b, of stress component c: in 2D xx, yy, xy; in
     * 3D xx, yy, zz, xy, xz, yz.
     */
    static std::pair<unsigned int, unsigned int>
    stress_component_indices(const unsigned int c);

    /**
     * The tensor that multiplies the scalar shape function of component c, so
     * that the dof value is the stress component itself: e_a (x) e_b + e_b (x)
     * e_a symmetrised, i.e. 1 on both (a,b) and (b,a).
     */
    static dealii::SymmetricTensor<2, dim>
    stress_basis_tensor(const unsigned int c);

    /** Component name (sxx, syy, sxy, ...). */
    static std::string
    stress_component_name(const unsigned int c);

    std::string stress_element_name = "DGQ1";

    std::unique_ptr<dealii::FESystem<dim>> fe_displacement;
    std::unique_ptr<dealii::FESystem<dim>> fe_stress;
    dealii::DoFHandler<dim>                dof_handler_displacement;
    dealii::DoFHandler<dim>                dof_handler_stress;
  };
} // namespace hrcontact

#endif
