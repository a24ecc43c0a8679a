#ifndef hrcontact_stress_element_h
#define hrcontact_stress_element_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/full_matrix.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * The discontinuous stress field of one cell (Finite elements/Stress
   * element). Every element is evaluated through a nodal DG element, one
   * scalar element per stress component (the *value element*: DGQ1, DGP1,
   * DGP0), whose dof values are the stress components themselves; the
   * output, the probes and the section forces read stresses in it. An
   * assumed-stress element (Pian-Sumihara) spans only a subspace of its
   * value element: its unknowns are the few parameters of that subspace,
   * numbered by a *parameter element* (one DGQ0 dof per parameter), and
   * the cell's value dofs are T_c beta_c. The assembler integrates B_c and
   * F_c in the value element and hands on B_c T_c and T_c^T F_c T_c, so
   * both Newton-step paths, the material laws and the stress constraints
   * see only the parameters and need no change.
   *
   * Each element registers itself by name with StressElementFactory.
   */
  template <int dim>
  class StressElement
  {
  public:
    virtual ~StressElement() = default;

    /** The nodal element the stresses are evaluated in. */
    virtual std::unique_ptr<dealii::FESystem<dim>>
    value_element() const = 0;

    /**
     * The element whose dofs are the unknowns, one DGQ0 dof per parameter;
     * null when the value dofs are the unknowns (T_c the identity).
     */
    virtual std::unique_ptr<dealii::FESystem<dim>>
    parameter_element() const
    {
      return nullptr;
    }

    /**
     * T_c (value dofs x parameters) of the cell: column p holds the value
     * dofs of parameter p's stress field. Depends on the cell's geometry
     * only; a translated cell has the same T_c. Called only when
     * parameter_element() is not null.
     */
    virtual void
    expansion(const typename dealii::Triangulation<dim>::cell_iterator &cell,
              const dealii::FiniteElement<dim> &value_fe,
              dealii::FullMatrix<double>       &T) const;
  };

  /** The name -> factory registry of stress elements. */
  template <int dim>
  class StressElementFactory
  {
  public:
    using Factory = std::function<std::unique_ptr<StressElement<dim>>()>;

    static bool
    register_element(const std::string &name,
                     const std::string &description,
                     const Factory     &factory);

    /** The names and descriptions, for the entry's documentation. */
    static std::string
    documentation();

    /** The element of that name; InputError naming the known ones if none. */
    static std::unique_ptr<StressElement<dim>>
    create(const std::string &name);

  private:
    struct Entry
    {
      std::string name, description;
      Factory     factory;
    };
    static std::vector<Entry> &
    registry();
  };
} // namespace hrcontact

#endif
