#ifndef hrcontact_refinement_indicator_h
#define hrcontact_refinement_indicator_h

#include <deal.II/lac/vector.h>

#include <hrcontact/core/results.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  /**
   * Where a solved mesh should be refined: one non-negative value per
   * active cell, larger where the error is (Mesh refinement/Estimator).
   * Each indicator registers itself by name with
   * HRCONTACT_REGISTER_REFINEMENT_INDICATOR; adding one touches one new
   * file pair.
   */
  template <int dim>
  class RefinementIndicator
  {
  public:
    virtual ~RefinementIndicator() = default;

    /**
     * Each of this process's own cells' indicator, indexed by
     * active_cell_index (zero for other cells); @p indicators has
     * n_active_cells() entries. Collective on a distributed mesh.
     */
    virtual void
    estimate(const Results<dim>    &results,
             dealii::Vector<float> &indicators) const = 0;

    /** Refuses (InputError) a scene the indicator cannot estimate, before
     * the first solve; nothing by default. */
    virtual void
    check(const Scene<dim> &) const
    {}

    /**
     * A guaranteed upper bound of the last estimate's energy error relative
     * to the energy of the computed stresses, where the indicator gives one
     * (Mesh refinement/Target error); empty otherwise.
     */
    virtual std::optional<double>
    relative_bound() const
    {
      return std::nullopt;
    }
  };

  /** The name -> factory registry of RefinementIndicator. */
  template <int dim>
  class RefinementIndicatorFactory
  {
  public:
    using Factory = std::function<std::unique_ptr<RefinementIndicator<dim>>()>;

    static bool
    register_indicator(const std::string &name,
                       const std::string &description,
                       const Factory     &factory);

    /** The indicator of that name (InputError naming the known ones). */
    static std::unique_ptr<RefinementIndicator<dim>>
    create(const std::string &name);

    /** The names, '|'-separated (a Patterns::Selection). */
    static std::string
    names();

    /** "name: description" of each, for the parameter's documentation. */
    static std::string
    descriptions();

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

/** Register CLASSNAME<2> and CLASSNAME<3> as indicator NAME. */
#define HRCONTACT_REGISTER_REFINEMENT_INDICATOR(classname, name, description) \
  namespace                                                                   \
  {                                                                           \
    const bool classname##_registered_2d =                                    \
      ::hrcontact::RefinementIndicatorFactory<2>::register_indicator(         \
        name,                                                                 \
        description,                                                          \
        []() { return std::make_unique<classname<2>>(); });                   \
    const bool classname##_registered_3d =                                    \
      ::hrcontact::RefinementIndicatorFactory<3>::register_indicator(         \
        name,                                                                 \
        description,                                                          \
        []() { return std::make_unique<classname<3>>(); });                   \
  }

#endif
