#include <deal.II/base/utilities.h>

#include <hrcontact/constraints/straight_obstacles.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  StraightObstacles<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Obstacles",
      "",
      Patterns::Anything(),
      "Rigid straight obstacles (a line in 2D, a plane in 3D) for frictionless "
      "unilateral contact, per boundary id of the body: 'id: x0, y0 [, z0] : "
      "nx, ny [, nz]', entries separated by '|'. (x0, ...) is a point of the "
      "obstacle and (nx, ...) its normal pointing into the obstacle (it is "
      "normalised); coordinates are expressions of the constants. Each node "
      "of the boundary gets one unilateral constraint w.n - g <= 0 with the "
      "gap g = (x0 - x).n, reaction p n with p <= 0. Empty: no contact.");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  StraightObstacles<dim>::entry() const
  {
    return "Contact/Obstacles";
  }

  template <int dim>
  bool
  StraightObstacles<dim>::acts_on(const types::boundary_id id) const
  {
    return obstacles.count(id) > 0;
  }

  template <int dim>
  std::vector<types::boundary_id>
  StraightObstacles<dim>::boundary_ids() const
  {
    return boundary_ids_of(obstacles);
  }

  template <int dim>
  bool
  StraightObstacles<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection("Contact");
    for (const BoundaryEntry &e : parse_boundary_list(
           prm.get("Obstacles"), dim, false, "Contact/Obstacles"))
      {
        const std::string where =
          "Contact/Obstacles, boundary " + std::to_string(e.boundary_id);
        const auto parts = split_and_trim(e.expressions, ':');
        if (parts.size() != 2)
          throw InputError(where + ": expected 'id: point : normal'.");
        Obstacle obstacle;
        for (unsigned int k = 0; k < 2; ++k)
          {
            const auto coords = split_and_trim(parts[k], ',');
            if (coords.size() != dim)
              throw InputError(where + ": expected " + std::to_string(dim) +
                               " coordinates separated by ',' in '" + parts[k] +
                               "'.");
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double v =
                  evaluate_constant_expression(coords[d], constants, where);
                if (k == 0)
                  obstacle.point[d] = v;
                else
                  obstacle.normal[d] = v;
              }
          }
        if (!(obstacle.normal.norm() > 0))
          throw InputError(where + ": the normal is zero.");
        obstacle.normal /= obstacle.normal.norm();
        require_unconstrained<dim>(e.boundary_id,
                                   where,
                                   earlier,
                                   "a bilateral normal constraint");
        obstacles[e.boundary_id] = obstacle;
      }
    prm.leave_subsection();
    return !obstacles.empty();
  }

  template <int dim>
  void
  StraightObstacles<dim>::collect(const BoundaryFace<dim> &face,
                                  const EquilibriumSystem &,
                                  NodeConstraintMap<dim> &nodes) const
  {
    // One constraint per obstacle at a node (several at a corner, eq. 11).
    const Obstacle &ob = obstacles.at(face.boundary_id);
    for (unsigned int v = 0; v < face.nodes.size(); ++v)
      nodes[face.nodes[v]].touch(face.boundary_id,
                                 ob.normal,
                                 (ob.point - face.points[v]) * ob.normal);
  }

  template class StraightObstacles<2>;
  template class StraightObstacles<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(StraightObstacles, 30)
} // namespace hrcontact
