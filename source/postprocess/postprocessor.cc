#include <deal.II/base/utilities.h>

#include <hrcontact/postprocess/postprocessor.h>

#include <algorithm>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  Postprocessor<dim>::parse_parameters(ParameterHandler &, const Constants &)
  {}

  template <int dim>
  std::string
  Postprocessor<dim>::skip_reason(const Results<dim> &) const
  {
    return "";
  }

  template <int dim>
  std::vector<typename PostprocessorManager<dim>::Entry> &
  PostprocessorManager<dim>::registry()
  {
    // Function-local: filled by static initialisers of other files.
    static std::vector<Entry> entries;
    return entries;
  }

  template <int dim>
  bool
  PostprocessorManager<dim>::register_postprocessor(
    const std::string                             &name,
    const std::string                             &description,
    const unsigned int                             position,
    const std::function<void(ParameterHandler &)> &declare,
    const Factory                                 &factory)
  {
    auto &entries = registry();
    for (const Entry &e : entries)
      AssertThrow(e.name != name,
                  ExcMessage("postprocessor '" + name +
                             "' is registered twice"));
    entries.push_back({name, description, position, declare, factory});
    std::stable_sort(entries.begin(),
                     entries.end(),
                     [](const Entry &a, const Entry &b) {
                       return a.position < b.position;
                     });
    return true;
  }

  template <int dim>
  std::vector<std::string>
  PostprocessorManager<dim>::registered_names()
  {
    std::vector<std::string> names;
    for (const Entry &e : registry())
      names.push_back(e.name);
    return names;
  }

  template <int dim>
  void
  PostprocessorManager<dim>::declare_parameters(ParameterHandler &prm)
  {
    std::string list;
    for (const Entry &e : registry())
      list += "\n  " + e.name + ": " + e.description;
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "List of postprocessors",
      "all",
      Patterns::Anything(),
      "What runs after the solve, in this order, separated by ','; 'all' runs "
      "every postprocessor that applies to the scene, in the order below "
      "(the order of summary.txt), and a name listed for a scene it does not "
      "apply to is skipped with a note. Available:" +
        list);
    prm.leave_subsection();
    for (const Entry &e : registry())
      e.declare(prm);
  }

  template <int dim>
  void
  PostprocessorManager<dim>::parse_parameters(ParameterHandler &prm,
                                              const Constants  &constants)
  {
    prm.enter_subsection("Postprocess");
    const std::string list = Utilities::trim(prm.get("List of postprocessors"));
    prm.leave_subsection();
    run_all = (list == "all");
    names   = run_all ? registered_names() : split_and_trim(list, ',');
    postprocessors.clear();
    for (const std::string &name : names)
      {
        const auto &entries = registry();
        const auto  e =
          std::find_if(entries.begin(), entries.end(), [&](const Entry &e) {
            return e.name == name;
          });
        if (e == entries.end())
          {
            std::string known;
            for (const Entry &k : entries)
              known += (known.empty() ? "" : ", ") + k.name;
            throw InputError("Postprocess/List of postprocessors: unknown "
                             "postprocessor '" +
                             name + "' (known: all, " + known + ").");
          }
        if (std::count(names.begin(), names.end(), name) > 1)
          throw InputError("Postprocess/List of postprocessors: '" + name +
                           "' is listed twice.");
        postprocessors.push_back(e->factory());
        postprocessors.back()->parse_parameters(prm, constants);
      }
  }

  template <int dim>
  void
  PostprocessorManager<dim>::execute(const Results<dim> &results,
                                     PostprocessOutput  &output) const
  {
    for (unsigned int k = 0; k < postprocessors.size(); ++k)
      {
        const std::string reason = postprocessors[k]->skip_reason(results);
        if (reason.empty())
          postprocessors[k]->execute(results, output);
        else if (!run_all)
          output.log << "  postprocessor '" << names[k]
                     << "' skipped: " << reason << std::endl;
      }
  }

  template <int dim>
  bool
  Postprocessor<dim>::needs_replicated_mesh(const Scene<dim> &) const
  {
    return false;
  }

  template <int dim>
  bool
  PostprocessorManager<dim>::needs_replicated_mesh(
    const Scene<dim> &scene) const
  {
    for (const auto &p : postprocessors)
      if (p->needs_replicated_mesh(scene))
        return true;
    return false;
  }

  template <int dim>
  void
  Postprocessor<dim>::check_input(const Scene<dim> &,
                                  const Triangulation<dim> &,
                                  const EquilibriumSystem &) const
  {}

  template <int dim>
  void
  PostprocessorManager<dim>::check_input(
    const Scene<dim>         &scene,
    const Triangulation<dim> &triangulation,
    const EquilibriumSystem  &system) const
  {
    for (const auto &p : postprocessors)
      p->check_input(scene, triangulation, system);
  }

  template class Postprocessor<2>;
  template class Postprocessor<3>;
  template class PostprocessorManager<2>;
  template class PostprocessorManager<3>;
} // namespace hrcontact
