#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/constraints/curved_obstacles.h>
#include <hrcontact/discretisation/hanging_nodes.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/discretisation/row_classification.h>
#include <hrcontact/solvers/newton_step_path.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  CurvedObstacles<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Curved obstacles",
      "",
      Patterns::Anything(),
      "Rigid curved obstacles for frictionless unilateral contact, per "
      "boundary id of the body, entries separated by '|': 'id: circle : xc, "
      "yc [, zc] : R' (a circle in 2D, in 3D a cylinder with its axis along "
      "z through (xc, yc)), 'id: sphere : xc, yc, zc : R', or 'id: level "
      "set : phi' with phi an expression in x, y (, z) that is negative "
      "inside the obstacle (best a signed distance). Each node of the "
      "boundary gets the constraint of the straight obstacle tangent at its "
      "nearest point on the surface (the paper's linearised case): normal "
      "n = -grad phi / |grad phi| there, pointing into the obstacle, and "
      "gap g = (x_surface - x).n.");
    prm.declare_entry(
      "Update curved obstacles",
      "true",
      Patterns::Bool(),
      "true: linearise the curved obstacles again at the current "
      "configuration x + u after every multiplier update (nearest point, "
      "normal and gap; needs the condensed path, which Path = automatic "
      "then takes). false: linearise them once, at the initial "
      "configuration (any path). For small displacements the difference "
      "is of second order in u / R (1.8e-5 of the force on "
      "cylinder-indentation.prm).");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  CurvedObstacles<dim>::entry() const
  {
    return "Contact/Curved obstacles";
  }

  template <int dim>
  bool
  CurvedObstacles<dim>::acts_on(const types::boundary_id id) const
  {
    return obstacles.count(id) > 0;
  }

  template <int dim>
  std::vector<types::boundary_id>
  CurvedObstacles<dim>::boundary_ids() const
  {
    return boundary_ids_of(obstacles);
  }

  template <int dim>
  bool
  CurvedObstacles<dim>::parse_parameters(
    ParameterHandler                                          &prm,
    const Constants                                           &constants,
    const std::vector<std::shared_ptr<ConstraintSource<dim>>> &earlier)
  {
    prm.enter_subsection("Contact");
    for (const BoundaryEntry &e : parse_boundary_list(
           prm.get("Curved obstacles"), dim, false, "Contact/Curved obstacles"))
      {
        const std::string where =
          "Contact/Curved obstacles, boundary " + std::to_string(e.boundary_id);
        require_unconstrained<dim>(
          e.boundary_id,
          where,
          earlier,
          "a normal constraint, an obstacle, a boundary support or a stop");
        const auto     parts = split_and_trim(e.expressions, ':');
        CurvedObstacle obstacle;
        if (!parts.empty() && parts[0] == "level set" && parts.size() == 2)
          {
            obstacle.shape = CurvedObstacle::Shape::level_set;
            obstacle.phi =
              make_function<dim>(parts[1], 1, constants, where + ", phi");
          }
        else if (!parts.empty() &&
                 (parts[0] == "circle" || parts[0] == "sphere") &&
                 parts.size() == 3)
          {
            obstacle.shape = (parts[0] == "circle") ?
                               CurvedObstacle::Shape::circle :
                               CurvedObstacle::Shape::sphere;
            if (obstacle.shape == CurvedObstacle::Shape::sphere && dim != 3)
              throw InputError(where + ": a sphere needs Dimension = 3 (use "
                                       "circle in 2D).");
            const auto         coords = split_and_trim(parts[1], ',');
            const unsigned int n_centre =
              (obstacle.shape == CurvedObstacle::Shape::circle) ? 2 : 3;
            if (coords.size() != n_centre)
              throw InputError(where + ": expected " +
                               std::to_string(n_centre) +
                               " centre coordinates in '" + parts[1] + "'.");
            for (unsigned int d = 0; d < n_centre; ++d)
              obstacle.centre[d] =
                evaluate_constant_expression(coords[d], constants, where);
            obstacle.radius =
              evaluate_constant_expression(parts[2], constants, where);
            if (!(obstacle.radius > 0))
              throw InputError(where + ": the radius must be positive.");
          }
        else
          throw InputError(
            where + ": expected 'id: circle : xc, yc [, zc] : R', 'id: "
                    "sphere : xc, yc, zc : R' or 'id: level set : phi'.");
        obstacles[e.boundary_id] = std::move(obstacle);
      }
    update = prm.get_bool("Update curved obstacles");
    prm.leave_subsection();
    return !obstacles.empty();
  }

  template <int dim>
  void
  CurvedObstacles<dim>::collect(const BoundaryFace<dim> &face,
                                const EquilibriumSystem &,
                                NodeConstraintMap<dim> &nodes) const
  {
    // The straight obstacle tangent at the nearest point of the surface.
    const CurvedObstacle &co = obstacles.at(face.boundary_id);
    for (unsigned int v = 0; v < face.nodes.size(); ++v)
      {
        const auto [surface, normal] = co.project(face.points[v]);
        nodes[face.nodes[v]].touch(face.boundary_id,
                                   normal,
                                   (surface - face.points[v]) * normal);
      }
  }

  template <int dim>
  bool
  CurvedObstacles<dim>::changes_rows() const
  {
    return update;
  }

  namespace
  {
    /**
     * The rows of the curved obstacles at the current configuration: each
     * becomes the straight obstacle tangent at the point of the surface
     * nearest to the node's current position X + u (the straight case of
     * eq. 10 at the current configuration): new normal n, gap g =
     * (x_surface - X) . n, with the node's prescribed components taken out
     * as at the start; the node's free rows complete the basis again.
     * Corner nodes (several obstacles) stay linearised at the start.
     */
    template <int dim>
    class Relinearisation : public RowRelinearisation
    {
    public:
      using Obstacles = std::map<types::boundary_id,
                                 typename CurvedObstacles<dim>::CurvedObstacle>;

      Relinearisation(const Obstacles &obstacles, EquilibriumSystem &system)
        : obstacles(obstacles)
        , system(system)
      {
        for (unsigned int r = 0; r < system.rows.size(); ++r)
          rows_of_node[system.rows[r].node].push_back(r);
      }

      bool
      relinearise(NewtonStepPath            &path,
                  const std::vector<double> &opening) override
      {
        // The tangent obstacle at the point of the surface nearest to the
        // current position X + u of each node (the straight case of eq. 10 at
        // the current configuration): new normal n, gap g = (x_surface - X).n,
        // with the prescribed components of the node taken out as the assembler
        // does; the node's free rows complete the basis again.
        std::vector<double> w(opening.size());
        for (unsigned int k = 0; k < w.size(); ++k)
          w[k] = system.rows[system.contact_rows[k]].value + opening[k];
        // Gathered on every process: each re-linearises every row.
        FieldVector u(system.n_displacement_dofs);
        path.displacements(w, u);
        const double u_max   = u.linfty_norm();
        bool         changed = false;
        for (const unsigned int r : system.contact_rows)
          {
            EquilibriumRow &row = system.rows[r];
            const auto      co  = obstacles.find(row.obstacle);
            // Corner nodes (several obstacles) stay linearised at the start.
            if (row.obstacle < 0 || co == obstacles.end() ||
                !row.direction.empty())
              continue;
            Point<dim> X, x;
            for (unsigned int d = 0; d < dim; ++d)
              {
                X[d] = system.node_coordinates[row.node][d];
                x[d] = X[d] + u[row.combination[d].first];
              }
            const auto [surface, n]            = co->second.project(x);
            Tensor<1, dim>              n_free = n;
            double                      g      = (surface - X) * n;
            std::vector<Tensor<1, dim>> taken;
            for (const unsigned int s : rows_of_node[row.node])
              if (system.rows[s].row_class == RowClass::prescribed)
                for (unsigned int d = 0; d < dim; ++d)
                  if (system.rows[s].combination[d].second == 1.)
                    {
                      g -= n[d] * system.rows[s].value;
                      n_free[d] = 0;
                      Tensor<1, dim> e;
                      e[d] = 1;
                      taken.push_back(e);
                    }
            const double length = n_free.norm();
            if (length < 1e-8)
              continue;
            n_free /= length;
            g /= length;
            // Changed: beyond 1e-8 of the displacements (the finite-difference
            // gradient of a level set is good to about that).
            double turn = 0;
            for (unsigned int d = 0; d < dim; ++d)
              turn += std::abs(n_free[d] - row.combination[d].second);
            if (std::abs(g - row.value) + turn * u_max >
                1e-8 * (u_max + std::abs(g)))
              changed = true;
            for (unsigned int d = 0; d < dim; ++d)
              row.combination[d].second = n_free[d];
            row.value = g;
            taken.push_back(n_free);
            // The free rows: the orthogonal complement, as the assembler has
            // it.
            const auto   complement = orthogonal_complement<dim>(taken);
            unsigned int next       = 0;
            for (const unsigned int s : rows_of_node[row.node])
              if (system.rows[s].row_class == RowClass::free &&
                  next < complement.size())
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    system.rows[s].combination[d].second = complement[next][d];
                  ++next;
                }
          }
        // The hanging shares follow the rows' new coefficients.
        add_hanging_shares(system);
        if (changed)
          path.rows_changed();
        return changed;
      }

    private:
      const Obstacles                                  &obstacles;
      EquilibriumSystem                                &system;
      std::map<unsigned int, std::vector<unsigned int>> rows_of_node;
    };
  } // namespace

  template <int dim>
  std::unique_ptr<RowRelinearisation>
  CurvedObstacles<dim>::relinearisation(EquilibriumSystem &system) const
  {
    if (!update)
      return nullptr;
    return std::make_unique<Relinearisation<dim>>(obstacles, system);
  }

  template <int dim>
  std::pair<Point<dim>, Tensor<1, dim>>
  CurvedObstacles<dim>::CurvedObstacle::project(const Point<dim> &x) const
  {
    if (shape != Shape::level_set)
      {
        // Circle (cylinder along z in 3D) or sphere.
        Tensor<1, dim> r = x - centre;
        if (shape == Shape::circle && dim == 3)
          r[dim - 1] = 0;
        const double length = r.norm();
        if (!(length > 1e-14 * radius))
          throw InputError("Contact/Curved obstacles: a node lies on the "
                           "centre (axis) of a circular obstacle, where the "
                           "nearest point is not defined.");
        return {x - r + radius * r / length, -r / length};
      }
    Point<dim> y = x;
    for (unsigned int it = 0; it < 50; ++it)
      {
        const double         value    = phi->value(y);
        const Tensor<1, dim> gradient = phi->gradient(y);
        const double         g2       = gradient.norm_square();
        if (!std::isfinite(value) || !(g2 > 0))
          throw InputError("Contact/Curved obstacles: the level set or its "
                           "gradient is not usable near a contact node.");
        y -= value / g2 * gradient;
        if (std::abs(value) <= 1e-13 * (1 + x.norm()))
          break;
      }
    const Tensor<1, dim> gradient = phi->gradient(y);
    return {y, -gradient / gradient.norm()};
  }

  template class CurvedObstacles<2>;
  template class CurvedObstacles<3>;

  HRCONTACT_REGISTER_CONSTRAINT_SOURCE(CurvedObstacles, 50)
} // namespace hrcontact
