#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/point_supports.h>

#include <cmath>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  PointSupports<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Supports");
    prm.declare_entry(
      "Point supports",
      "",
      Patterns::Anything(),
      "Displacement components fixed at single nodes of a boundary: "
      "'id (point) [components]: values', entries separated by '|', e.g. "
      "'2 (0.5, 0) x: 0' holds u_x = 0 at the node of boundary 2 at (0.5, "
      "0). Components are letters x, y, z (all if omitted), one value per "
      "named component (constants allowed). The point must be a node of "
      "that boundary. Use it to hold a rigid motion where holding a whole "
      "boundary would also hold a deformation.");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  PointSupports<dim>::entry() const
  {
    return "Supports/Point supports";
  }

  template <int dim>
  bool
  PointSupports<dim>::acts_on(const types::boundary_id id) const
  {
    return supports.count(id) > 0;
  }

  template <int dim>
  std::vector<types::boundary_id>
  PointSupports<dim>::boundary_ids() const
  {
    std::vector<types::boundary_id> ids;
    for (const auto &[id, support] : supports)
      if (ids.empty() || ids.back() != id)
        ids.push_back(id);
    return ids;
  }

  template <int dim>
  bool
  PointSupports<dim>::is_normal_kind() const
  {
    return false;
  }

  template <int dim>
  bool
  PointSupports<dim>::parse_parameters(
    ParameterHandler &prm,
    const Constants  &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &)
  {
    prm.enter_subsection("Supports");
    const std::string text = prm.get("Point supports");
    prm.leave_subsection();
    const std::string where = "Supports/Point supports";
    for (const std::string &item : split_and_trim(text, '|'))
      {
        if (item.empty())
          continue;
        // 'id (point) [components]: values': the point cut out, the rest
        // is a per-boundary entry like Prescribed displacements'.
        const auto open = item.find('('), close = item.find(')');
        if (open == std::string::npos || close == std::string::npos ||
            close < open)
          throw InputError(where + ": '" + item +
                           "' is not 'id (point) [components]: values'.");
        const BoundaryEntry e =
          parse_boundary_list(item.substr(0, open) + item.substr(close + 1),
                              dim,
                              true,
                              where)
            .front();
        Support    s;
        const auto coordinates =
          split_and_trim(item.substr(open + 1, close - open - 1), ',');
        if (coordinates.size() != dim)
          throw InputError(where + ": the point of '" + item + "' needs " +
                           std::to_string(dim) + " coordinates.");
        for (unsigned int d = 0; d < dim; ++d)
          s.point[d] =
            evaluate_constant_expression(coordinates[d], constants, where);
        s.components        = e.components;
        const auto function = make_function<dim>(e.expressions,
                                                 e.components.size(),
                                                 constants,
                                                 where);
        for (unsigned int k = 0; k < e.components.size(); ++k)
          s.values.push_back(function->value(s.point, k));
        supports.emplace(e.boundary_id, s);
      }
    return !supports.empty();
  }

  template <int dim>
  bool
  PointSupports<dim>::at(const BoundaryFace<dim> &face,
                         const Point<dim>        &x,
                         const Point<dim>        &point)
  {
    double size = 0;
    for (const auto &p : face.points)
      size = std::max(size, p.distance(face.points[0]));
    return x.distance(point) <= 1e-8 * size;
  }

  template <int dim>
  void
  PointSupports<dim>::prepare(const std::vector<BoundaryFace<dim>> &faces,
                              const EquilibriumSystem &) const
  {
    for (const auto &[id, s] : supports)
      {
        bool found = false;
        for (const auto &face : faces)
          if (face.boundary_id == id)
            for (const auto &x : face.points)
              found = found || at(face, x, s.point);
        if (!found)
          {
            std::ostringstream p;
            for (unsigned int d = 0; d < dim; ++d)
              p << (d ? ", " : "") << s.point[d];
            throw InputError("Supports/Point supports: no node of boundary " +
                             std::to_string(id) + " at (" + p.str() +
                             "); the point must be a vertex of the mesh on "
                             "that boundary.");
          }
      }
  }

  template <int dim>
  void
  PointSupports<dim>::collect(const BoundaryFace<dim> &face,
                              const EquilibriumSystem &system,
                              NodeConstraintMap<dim>  &nodes) const
  {
    const auto range = supports.equal_range(face.boundary_id);
    for (auto it = range.first; it != range.second; ++it)
      for (unsigned int v = 0; v < face.nodes.size(); ++v)
        if (at(face, face.points[v], it->second.point))
          {
            NodeConstraints<dim> &c = nodes[face.nodes[v]];
            const Support        &s = it->second;
            for (unsigned int k = 0; k < s.components.size(); ++k)
              if (!c.prescribe(s.components[k], s.values[k]))
                throw InputError("Supports/Point supports: component " +
                                 std::string(1, "xyz"[s.components[k]]) +
                                 " at " + system.describe_node(face.nodes[v]) +
                                 " is already prescribed with another value.");
          }
  }

  template class PointSupports<2>;
  template class PointSupports<3>;
  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(PointSupports, 15)
} // namespace hrcontact
