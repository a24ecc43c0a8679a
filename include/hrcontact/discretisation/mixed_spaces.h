#ifndef hrcontact_mixed_spaces_h
#define hrcontact_mixed_spaces_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/stress_element.h>

#include <memory>
#include <string>

namespace hrcontact
{
  /**
   * The two discrete spaces of the Hellinger-Reissner discretisation (eq. 30):
   * continuous Q1 displacements and discontinuous stresses, one scalar DG
   * element per independent component of the symmetric tensor (the value
   * element), or an assumed-stress field spanning part of it (StressElement:
   * the unknowns are then the field's parameters). Stress dofs never couple
   * across cells, so the flexibility F is block diagonal.
   *
   * Two numberings of the stresses: dof_handler_stress numbers the value
   * dofs, in which Results::stress, the output and every postprocessor
   * read the field; stress_unknowns() numbers the unknowns of the
   * EquilibriumSystem and the solvers (the same handler unless the element
   * has parameters).
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

    /** The handler numbering the stress unknowns (see above). */
    const dealii::DoFHandler<dim> &
    stress_unknowns() const
    {
      return fe_stress_parameters ? dof_handler_stress_parameters :
                                    dof_handler_stress;
    }

    /** Whether the unknowns are parameters of a subspace (T_c != I). */
    bool
    has_parameters() const
    {
      return static_cast<bool>(fe_stress_parameters);
    }

    /** T_c of the cell (StressElement::expansion); needs has_parameters(). */
    void
    cell_expansion(
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      dealii::FullMatrix<double>                               &T) const;

    /**
     * The value dofs of a cell from a vector of stress unknowns; `cell` is
     * any iterator to it. The cell must be one this process holds.
     */
    void
    cell_values(const typename dealii::Triangulation<dim>::cell_iterator &cell,
                const FieldVector      &unknowns,
                dealii::Vector<double> &values) const;

    /**
     * Stress values (numbered by dof_handler_stress, sized by reinit_field)
     * from stress unknowns (by stress_unknowns()): the same vector unless
     * the element has parameters. On a distributed mesh each process
     * expands its own cells and the ghosts are imported.
     */
    void
    expand(const FieldVector &unknowns, FieldVector &values) const;

    std::string stress_element_name = "DGQ1";

    std::unique_ptr<StressElement<dim>>    stress_element;
    std::unique_ptr<dealii::FESystem<dim>> fe_displacement;
    /** The value element (DGQ1 for an assumed-stress field). */
    std::unique_ptr<dealii::FESystem<dim>> fe_stress;
    /** The parameter element; null when the values are the unknowns. */
    std::unique_ptr<dealii::FESystem<dim>> fe_stress_parameters;
    dealii::DoFHandler<dim>                dof_handler_displacement;
    dealii::DoFHandler<dim>                dof_handler_stress;
    /** Used only with fe_stress_parameters. */
    dealii::DoFHandler<dim> dof_handler_stress_parameters;
  };
} // namespace hrcontact

#endif
