#include <deal.II/base/exceptions.h>

#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_dgq.h>

#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/stress_element.h>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  StressElement<dim>::expansion(
    const typename Triangulation<dim>::cell_iterator &,
    const FiniteElement<dim> &,
    FullMatrix<double> &) const
  {
    AssertThrow(false,
                ExcMessage("StressElement::expansion: this element's value "
                           "dofs are its unknowns."));
  }

  template <int dim>
  std::vector<typename StressElementFactory<dim>::Entry> &
  StressElementFactory<dim>::registry()
  {
    // Function-local: filled by static initialisers of other files.
    static std::vector<Entry> entries;
    return entries;
  }

  template <int dim>
  bool
  StressElementFactory<dim>::register_element(const std::string &name,
                                              const std::string &description,
                                              const Factory     &factory)
  {
    for (const Entry &e : registry())
      AssertThrow(e.name != name,
                  ExcMessage("StressElementFactory: '" + name +
                             "' is registered twice"));
    registry().push_back({name, description, factory});
    return true;
  }

  template <int dim>
  std::string
  StressElementFactory<dim>::documentation()
  {
    std::string text;
    for (const Entry &e : registry())
      text += (text.empty() ? "" : "; ") + e.name + ": " + e.description;
    return text;
  }

  template <int dim>
  std::unique_ptr<StressElement<dim>>
  StressElementFactory<dim>::create(const std::string &name)
  {
    std::string names;
    for (const Entry &e : registry())
      {
        if (e.name == name)
          return e.factory();
        names += (names.empty() ? "" : ", ") + e.name;
      }
    throw InputError("Finite elements/Stress element: unknown element '" +
                     name + "' (known: " + names + ").");
  }

  namespace
  {
    /**
     * A standard DG element per stress component: the value dofs are the
     * unknowns.
     */
    template <int dim>
    class NodalStressElement : public StressElement<dim>
    {
    public:
      using Base = std::function<std::unique_ptr<FiniteElement<dim>>()>;
      explicit NodalStressElement(const Base &base)
        : base(base)
      {}
      std::unique_ptr<FESystem<dim>>
      value_element() const override
      {
        return std::make_unique<FESystem<dim>>(*base(), dim * (dim + 1) / 2);
      }

    private:
      Base base;
    };

    template <int dim>
    bool
    register_nodal()
    {
      const auto nodal = [](auto make) {
        return
          [make]() { return std::make_unique<NodalStressElement<dim>>(make); };
      };
      StressElementFactory<dim>::register_element(
        "DGQ1",
        "bilinear (trilinear) per cell and component; on parallelograms the "
        "HR solution equals the Q1 displacement solution, and shares its "
        "locking",
        nodal([] { return std::make_unique<FE_DGQ<dim>>(1); }));
      StressElementFactory<dim>::register_element(
        "DGP1", "linear per cell and component", nodal([] {
          return std::make_unique<FE_DGP<dim>>(1);
        }));
      StressElementFactory<dim>::register_element(
        "DGP0",
        "constant per cell and component; too poor for most meshes: the "
        "equilibrium reduction reports the resulting mechanisms",
        nodal([] { return std::make_unique<FE_DGP<dim>>(0); }));
      return true;
    }
    const bool registered_2d = register_nodal<2>();
    const bool registered_3d = register_nodal<3>();
  } // namespace

  template class StressElement<2>;
  template class StressElement<3>;
  template class StressElementFactory<2>;
  template class StressElementFactory<3>;
} // namespace hrcontact
