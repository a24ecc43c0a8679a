#include <hrcontact/adaptivity/refinement_indicator.h>
#include <hrcontact/core/input.h>

namespace hrcontact
{
  template <int dim>
  std::vector<typename RefinementIndicatorFactory<dim>::Entry> &
  RefinementIndicatorFactory<dim>::registry()
  {
    static std::vector<Entry> entries;
    return entries;
  }

  template <int dim>
  bool
  RefinementIndicatorFactory<dim>::register_indicator(
    const std::string &name,
    const std::string &description,
    const Factory     &factory)
  {
    registry().push_back({name, description, factory});
    return true;
  }

  template <int dim>
  std::unique_ptr<RefinementIndicator<dim>>
  RefinementIndicatorFactory<dim>::create(const std::string &name)
  {
    for (const auto &entry : registry())
      if (entry.name == name)
        return entry.factory();
    throw InputError("Mesh refinement/Estimator = " + name +
                     ": not a known estimator (" + names() + ").");
  }

  template <int dim>
  std::string
  RefinementIndicatorFactory<dim>::names()
  {
    std::string list;
    for (const auto &entry : registry())
      list += (list.empty() ? "" : "|") + entry.name;
    return list;
  }

  template <int dim>
  std::string
  RefinementIndicatorFactory<dim>::descriptions()
  {
    std::string text;
    for (const auto &entry : registry())
      text +=
        (text.empty() ? "" : "; ") + entry.name + ": " + entry.description;
    return text;
  }

  template class RefinementIndicatorFactory<2>;
  template class RefinementIndicatorFactory<3>;
} // namespace hrcontact
