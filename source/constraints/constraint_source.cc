#include <hrcontact/constraints/constraint_source.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  bool
  NodeConstraints<dim>::any_prescribed() const
  {
    return std::any_of(prescribed.begin(), prescribed.end(), [](bool b) {
      return b;
    });
  }

  template <int dim>
  bool
  NodeConstraints<dim>::prescribe(const unsigned int d, const double value)
  {
    if (prescribed[d] &&
        std::abs(prescribed_value[d] - value) > 1e-10 * (1 + std::abs(value)))
      return false;
    prescribed[d]       = true;
    prescribed_value[d] = value;
    return true;
  }

  template <int dim>
  void
  NodeConstraints<dim>::touch(const types::boundary_id id,
                              const Tensor<1, dim>    &normal,
                              const double             node_gap)
  {
    bool known = false;
    for (const auto &[other, n, g] : obstacles)
      known |= (other == id);
    if (!known)
      obstacles.emplace_back(id, normal, node_gap);
    obstacle        = id;
    obstacle_normal = normal;
    gap             = node_gap;
  }

  template <int dim>
  bool
  ConstraintSource<dim>::is_normal_kind() const
  {
    return true;
  }

  template <int dim>
  OwnRow
  ConstraintSource<dim>::own_row(const unsigned int,
                                 const Point<dim> &,
                                 const NodeConstraints<dim> &,
                                 const EquilibriumSystem &) const
  {
    AssertThrow(false, ExcInternalError());
    return OwnRow();
  }

  template <int dim>
  void
  ConstraintSource<dim>::prepare(const std::vector<BoundaryFace<dim>> &,
                                 const EquilibriumSystem &) const
  {}

  template <int dim>
  void
  ConstraintSource<dim>::couple_rows(EquilibriumSystem &) const
  {}

  template <int dim>
  bool
  ConstraintSource<dim>::changes_rows() const
  {
    return false;
  }

  template <int dim>
  std::unique_ptr<RowRelinearisation>
  ConstraintSource<dim>::relinearisation(EquilibriumSystem &) const
  {
    return nullptr;
  }

  template <int dim>
  void
  require_unconstrained(
    const types::boundary_id                                   id,
    const std::string                                         &where,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier,
    const std::string                                         &what)
  {
    for (const auto &source : earlier)
      if (source->is_normal_kind() && source->acts_on(id))
        throw InputError(where + ": boundary " + std::to_string(id) +
                         " already has " + what + ".");
  }

  template <int dim>
  std::vector<typename ConstraintSources<dim>::Entry> &
  ConstraintSources<dim>::registry()
  {
    // Function-local: filled by static initialisers of other files.
    static std::vector<Entry> entries;
    return entries;
  }

  template <int dim>
  bool
  ConstraintSources<dim>::register_source(
    const unsigned int                             position,
    const std::function<void(ParameterHandler &)> &declare,
    const Factory                                 &factory)
  {
    auto &entries = registry();
    entries.push_back({position, declare, factory});
    std::stable_sort(entries.begin(),
                     entries.end(),
                     [](const Entry &a, const Entry &b) {
                       return a.position < b.position;
                     });
    return true;
  }

  template <int dim>
  void
  ConstraintSources<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (const Entry &e : registry())
      e.declare(prm);
  }

  template <int dim>
  std::vector<std::shared_ptr<ConstraintSource<dim>>>
  ConstraintSources<dim>::create(ParameterHandler &prm,
                                 const Constants  &constants)
  {
    std::vector<std::shared_ptr<ConstraintSource<dim>>> sources;
    for (const Entry &e : registry())
      {
        std::shared_ptr<ConstraintSource<dim>> source = e.factory();
        if (source->parse_parameters(prm, constants, sources))
          sources.push_back(source);
      }
    return sources;
  }

  template void
  require_unconstrained<2>(
    const types::boundary_id,
    const std::string &,
    const std::vector<std::shared_ptr<ConstraintSource<2>>> &,
    const std::string &);
  template void
  require_unconstrained<3>(
    const types::boundary_id,
    const std::string &,
    const std::vector<std::shared_ptr<ConstraintSource<3>>> &,
    const std::string &);
  template struct NodeConstraints<2>;
  template struct NodeConstraints<3>;
  template class ConstraintSource<2>;
  template class ConstraintSource<3>;
  template class ConstraintSources<2>;
  template class ConstraintSources<3>;
} // namespace hrcontact
