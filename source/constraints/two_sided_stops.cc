#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/two_sided_stops.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::shared_ptr<const ConstraintLaw>
  two_sided_stop_at(const std::array<const FunctionParser<dim> *, 6> &values,
                    const Point<dim>                                 &point,
                    const std::string                                &where)
  {
    double v[6] = {0, 0, 0, 0, 0, 0};
    for (unsigned int k = 0; k < 6; ++k)
      if (values[k])
        {
          v[k] = values[k]->value(point);
          if (!std::isfinite(v[k]))
            throw InputError(where + ": a stop value is not finite.");
        }
    try
      {
        return std::make_shared<TwoSidedStop>(
          v[0], v[1], v[2], v[3], v[4], v[5]);
      }
    catch (const InputError &e)
      {
        throw InputError(where + ": " + e.what());
      }
  }

  template std::shared_ptr<const ConstraintLaw>
  two_sided_stop_at<2>(const std::array<const FunctionParser<2> *, 6> &,
                       const Point<2> &,
                       const std::string &);
  template std::shared_ptr<const ConstraintLaw>
  two_sided_stop_at<3>(const std::array<const FunctionParser<3> *, 6> &,
                       const Point<3> &,
                       const std::string &);

  template <int dim>
  void
  TwoSidedStops<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Stops",
      "",
      Patterns::Anything(),
      "Two-sided stops with limit reactions (section 2.4.2, Fig. 4), e.g. "
      "the seismic stops of a bridge bearing, per boundary id: 'id: dx, dy "
      "[, dz] : g- : g+ : p0- : p0+ [: k- : k+]', entries separated by '|'. "
      "Each node of the boundary gets one constraint on w = u.d (d the "
      "direction, normalised; constants): free travel for g- < w < g+; at "
      "w = g+ a reaction p d with p in [p0-, 0] (pushing back), at w = g- "
      "one with p in [0, p0+] (pulling back); beyond a stop the node moves "
      "on with the limit reaction, or along a branch of stiffness k- "
      "(beyond g+) or k+ (beyond g-) when given (0: constant). g-, g+ are "
      "lengths, p0-, p0+ nodal forces (per unit thickness in 2D), k "
      "stiffnesses; each an expression in x, y (, z) evaluated at the node. "
      "Needs g- < g+, p0- <= 0 <= p0+, k >= 0. The direction must not "
      "have a part along a prescribed displacement component of the node. "
      "Empty: none.");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  TwoSidedStops<dim>::entry() const
  {
    return "Contact/Stops";
  }

  template <int dim>
  bool
  TwoSidedStops<dim>::acts_on(const types::boundary_id id) const
  {
    return stops.count(id) > 0;
  }

  template <int dim>
  std::vector<types::boundary_id>
  TwoSidedStops<dim>::boundary_ids() const
  {
    return boundary_ids_of(stops);
  }

  template <int dim>
  bool
  TwoSidedStops<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection("Contact");
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get("Stops"), dim, false, "Contact/Stops"))
      {
        const std::string where =
          "Contact/Stops, boundary " + std::to_string(e.boundary_id);
        require_unconstrained<dim>(
          e.boundary_id,
          where,
          earlier,
          "a normal constraint, an obstacle, a boundary support or a stop");
        const auto parts = split_and_trim(e.expressions, ':');
        if (parts.size() != 5 && parts.size() != 7)
          throw InputError(where +
                           ": expected 'id: direction : g- : g+ : p0- : p0+' "
                           "or with ': k- : k+' added, found " +
                           std::to_string(parts.size()) + " fields.");
        Stop       stop;
        const auto coords = split_and_trim(parts[0], ',');
        if (coords.size() != dim)
          throw InputError(where + ": expected " + std::to_string(dim) +
                           " direction components separated by ',' in '" +
                           parts[0] + "'.");
        for (unsigned int d = 0; d < dim; ++d)
          stop.direction[d] =
            evaluate_constant_expression(coords[d], constants, where);
        if (!(stop.direction.norm() > 0))
          throw InputError(where + ": the direction is zero.");
        stop.direction /= stop.direction.norm();
        const char *names[6] = {"g-", "g+", "p0-", "p0+", "k-", "k+"};
        for (unsigned int k = 1; k < parts.size(); ++k)
          stop.values[k - 1] = make_function<dim>(parts[k],
                                                  1,
                                                  constants,
                                                  where + ", " + names[k - 1]);
        stops[e.boundary_id] = std::move(stop);
      }
    prm.leave_subsection();
    return !stops.empty();
  }

  template <int dim>
  void
  TwoSidedStops<dim>::collect(const BoundaryFace<dim> &face,
                              const EquilibriumSystem &system,
                              NodeConstraintMap<dim>  &nodes) const
  {
    const int id = face.boundary_id;
    for (const unsigned int node : face.nodes)
      {
        NodeConstraints<dim> &c = nodes[node];
        if (c.own_row_source && c.own_row_boundary != id)
          throw InputError("Contact/Stops: " + system.describe_node(node) +
                           " has the stops of boundaries " +
                           std::to_string(c.own_row_boundary) + " and " +
                           std::to_string(id) + "; one stop per node.");
        c.own_row_source   = this;
        c.own_row_boundary = id;
      }
  }

  template <int dim>
  OwnRow
  TwoSidedStops<dim>::own_row(const unsigned int          node,
                              const Point<dim>           &point,
                              const NodeConstraints<dim> &constraints,
                              const EquilibriumSystem    &system) const
  {
    const Stop       &stop  = stops.at(constraints.own_row_boundary);
    const std::string where = "Contact/Stops, boundary " +
                              std::to_string(constraints.own_row_boundary) +
                              ", " + system.describe_node(node);
    if (constraints.has_normal || constraints.obstacle >= 0)
      throw InputError(where + ": the node also has a normal constraint, an "
                               "obstacle or a boundary support.");
    for (unsigned int d = 0; d < dim; ++d)
      if (constraints.prescribed[d] && std::abs(stop.direction[d]) > 1e-12)
        throw InputError(where +
                         ": the stop direction has a part along the "
                         "prescribed displacement component " +
                         std::string(1, "xyz"[d]) + ".");
    std::array<const FunctionParser<dim> *, 6> values;
    for (unsigned int k = 0; k < 6; ++k)
      values[k] = stop.values[k].get();
    const auto law = two_sided_stop_at<dim>(values, point, where);
    OwnRow     row;
    for (unsigned int d = 0; d < dim; ++d)
      row.direction.push_back(stop.direction[d]);
    row.law = law;
    return row;
  }

  template class TwoSidedStops<2>;
  template class TwoSidedStops<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(TwoSidedStops, 60)
} // namespace hrcontact
