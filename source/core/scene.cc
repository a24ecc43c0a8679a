#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <hrcontact/core/scene.h>

#include <cmath>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  Scene<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Constants",
      "",
      Patterns::Anything(),
      "Named constants for use in every expression of this file, as a comma "
      "separated list 'name = expression'; later constants may use earlier "
      "ones, e.g. 'L = 10, D = 1, I = D^3/12'.");

    prm.enter_subsection("Geometry");
    {
      prm.declare_entry(
        "Grid generator",
        "hyper_cube",
        Patterns::Anything(),
        "Name of a deal.II GridGenerator function, e.g. hyper_cube, "
        "subdivided_hyper_rectangle, hyper_shell, or one of ours: "
        "half_cylinder (the "
        "half model of a cylinder of radius R on the plane y = -R, graded "
        "towards the contact point; arguments R : phi_c : q, half the surface "
        "nodes lie uniformly on the arc phi_c (radians, <= pi/4) next to the "
        "contact point, q >= 1 thins the layers towards the surface; ids 0 "
        "symmetry x = 0, 1 loaded "
        "diameter y = 0, 2 curved surface); tunnel_lining (the right half, "
        "x >= 0, of a lining of two circular arcs; arguments R_c : R_i : H : "
        "t_c : t_i [: cells across], expressions of the constants: intrados "
        "crown radius centred at the origin, invert radius centred on x = 0, "
        "clear height, crown and invert thickness, coarse cells across the "
        "thickness (default 1); ids 0 intrados, 1 extrados, 2 symmetry cut "
        "at the crown, 3 symmetry cut at the invert; see doc/tunnel.md); "
        "wedge_block (a parallelogram with one corner at the origin, edges "
        "(L_a, 0) and L_b (cos theta, sin theta); arguments L_a : L_b : theta "
        "(degrees) : n_a : n_b cells along them; ids 0 the face along the "
        "second edge, 1 its opposite, 2 the face along the first edge, 3 its "
        "opposite). For "
        "deal.II grids the boundary "
        "ids are those the generator assigns (use colorize = true for a rectangle: 0 left, "
        "1 right, 2 bottom, 3 top, in 3D 4 back, 5 front).");
      prm.declare_entry(
        "Grid arguments",
        "0 : 1 : true",
        Patterns::Anything(),
        "Arguments of the grid generator, separated by ':' in the order of "
        "its C++ signature, e.g. for subdivided_hyper_rectangle "
        "'8, 2 : 0, 0 : 4, 1 : true' (subdivisions : corner : opposite corner "
        ": colorize).");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 12),
                        "Number of uniform refinements of the generated grid.");
      prm.declare_entry(
        "Distortion",
        "0",
        Patterns::Double(0, 0.4),
        "Move every interior vertex randomly by up to this fraction of the "
        "adjacent cells' size (reproducible seed; the boundary stays put). "
        "Used for patch tests on distorted meshes.");
      prm.declare_entry(
        "Rotation angle",
        "0",
        Patterns::Double(),
        "Rotate the whole mesh about the origin (about the z axis in 3D) by "
        "this angle in degrees, after refinement and distortion.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      prm.declare_entry("Young's modulus",
                        "1",
                        Patterns::Anything(),
                        "Young's modulus E (an expression of constants); > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.3",
                        Patterns::Anything(),
                        "Poisson's ratio nu (an expression of constants); in "
                        "(-1, 0.5), and below 0.5 in 3D and plane strain.");
      prm.declare_entry(
        "Plane condition",
        "plane strain",
        Patterns::Selection("plane strain|plane stress"),
        "2D only: plane strain (eps_zz = 0, reactions per unit thickness) or "
        "plane stress (sigma_zz = 0).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Loads");
    {
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Body force per unit volume, one expression per "
                        "component separated by ';', in x, y (, z) and the "
                        "constants. Empty: none.");
      prm.declare_entry(
        "Tractions",
        "",
        Patterns::Anything(),
        "Surface tractions (force per unit area, global components) per "
        "boundary id: 'id: tx; ty [; tz]', entries separated by '|', e.g. "
        "'1: 0; -100*x | 3: 50; 0'. Empty: none.");
      prm.declare_entry(
        "Projected pressures",
        "",
        Patterns::Anything(),
        "Earth-pressure-like loads per boundary id: 'id: px; py [; pz]', "
        "entries separated by '|'. p_k (force per unit area, positive "
        "pressing on the body) acts on the projection of the surface normal "
        "to axis k: the traction is t_k = -p_k n_k (no sum), n the outward "
        "normal. px = py = p is a normal pressure p; 'py = q' alone puts a "
        "vertical load q per unit horizontal length on a curved roof. "
        "Empty: none.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Supports");
    {
      prm.declare_entry(
        "Prescribed displacements",
        "",
        Patterns::Anything(),
        "Prescribed displacement components (the H rows) per boundary id: "
        "'id [components]: values', entries separated by '|'. Components are "
        "letters x, y, z (all if omitted), with one expression per named "
        "component, e.g. '0: 0; 0 | 2 y: -1e-3'. Where two ids meet, their "
        "values must agree.");
      prm.declare_entry(
        "Normal displacements",
        "",
        Patterns::Anything(),
        "Bilateral constraints u.n = g (the Q rows, eq. 38) per boundary id: "
        "'id: g', entries separated by '|'. n is the outward unit normal of "
        "the body at each boundary node (face normals averaged); the node's "
        "rows are rotated to (n, tangents) and the tangential ones stay free. "
        "Where a node also has prescribed components, the constraint acts on the "
        "free part of the displacement: n_free . u_free = g - n . u-hat, with "
        "n_free the part of n off the prescribed axes (no row if it vanishes).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Contact");
    {
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
      prm.declare_entry(
        "Boundary supports",
        "",
        Patterns::Anything(),
        "Unilateral frictionless supports along the body's own boundary, "
        "against a rigid surrounding medium (e.g. the ground around a tunnel "
        "lining): 'id: g', entries separated by '|', with g the initial gap "
        "(an expression in x, y (, z); 0 for a medium in contact). Each node "
        "of the boundary gets w.n - g <= 0 with n the outward normal of the "
        "body at the node (face normals averaged), the same constraint as an "
        "obstacle. Empty: none.");
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
    }
    prm.leave_subsection();
  }

  template <int dim>
  void
  Scene<dim>::parse_parameters(ParameterHandler &prm)
  {
    constants = parse_constants(prm.get("Constants"), "Constants");

    prm.enter_subsection("Geometry");
    {
      grid_generator     = Utilities::trim(prm.get("Grid generator"));
      grid_arguments     = prm.get("Grid arguments");
      global_refinements = prm.get_integer("Global refinements");
      distortion         = prm.get_double("Distortion");
      rotation_degrees   = prm.get_double("Rotation angle");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      youngs_modulus = evaluate_constant_expression(prm.get("Young's modulus"),
                                                    constants,
                                                    "Material/Young's modulus");
      poisson_ratio  = evaluate_constant_expression(prm.get("Poisson's ratio"),
                                                   constants,
                                                   "Material/Poisson's ratio");
      plane_strain   = (prm.get("Plane condition") == "plane strain");
    }
    prm.leave_subsection();
    if (!(youngs_modulus > 0))
      throw InputError("Material/Young's modulus must be positive (got " +
                       std::to_string(youngs_modulus) + ").");
    const bool incompressible_limit_matters = (dim == 3 || plane_strain);
    if (!(poisson_ratio > -1) ||
        (incompressible_limit_matters ? !(poisson_ratio < 0.5) :
                                        !(poisson_ratio <= 0.5)))
      throw InputError("Material/Poisson's ratio " +
                       std::to_string(poisson_ratio) +
                       " is outside (-1, 0.5): the compliance would not be "
                       "positive definite.");

    prm.enter_subsection("Loads");
    {
      const std::string b = prm.get("Body force");
      if (!Utilities::trim(b).empty())
        body_force = make_function<dim>(b, dim, constants, "Loads/Body force");
      for (const BoundaryEntry &e : parse_boundary_list(
             prm.get("Tractions"), dim, false, "Loads/Tractions"))
        tractions[e.boundary_id] =
          make_function<dim>(e.expressions,
                             dim,
                             constants,
                             "Loads/Tractions, boundary " +
                               std::to_string(e.boundary_id));
      for (const BoundaryEntry &e :
           parse_boundary_list(prm.get("Projected pressures"),
                               dim,
                               false,
                               "Loads/Projected pressures"))
        projected_pressures[e.boundary_id] =
          make_function<dim>(e.expressions,
                             dim,
                             constants,
                             "Loads/Projected pressures, boundary " +
                               std::to_string(e.boundary_id));
    }
    prm.leave_subsection();

    prm.enter_subsection("Supports");
    {
      for (const BoundaryEntry &e :
           parse_boundary_list(prm.get("Prescribed displacements"),
                               dim,
                               true,
                               "Supports/Prescribed displacements"))
        {
          PrescribedDisplacement &pd = prescribed_displacements[e.boundary_id];
          pd.components              = e.components;
          pd.values =
            make_function<dim>(e.expressions,
                               e.components.size(),
                               constants,
                               "Supports/Prescribed displacements, boundary " +
                                 std::to_string(e.boundary_id));
        }
      for (const BoundaryEntry &e :
           parse_boundary_list(prm.get("Normal displacements"),
                               dim,
                               false,
                               "Supports/Normal displacements"))
        normal_displacements[e.boundary_id] =
          make_function<dim>(e.expressions,
                             1,
                             constants,
                             "Supports/Normal displacements, boundary " +
                               std::to_string(e.boundary_id));
    }
    prm.leave_subsection();

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
        if (normal_displacements.count(e.boundary_id))
          throw InputError(where + ": boundary " +
                           std::to_string(e.boundary_id) +
                           " already has a bilateral normal constraint.");
        obstacles[e.boundary_id] = obstacle;
      }
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get("Boundary supports"),
                             dim,
                             false,
                             "Contact/Boundary supports"))
      {
        const std::string where = "Contact/Boundary supports, boundary " +
                                  std::to_string(e.boundary_id);
        if (normal_displacements.count(e.boundary_id) ||
            obstacles.count(e.boundary_id))
          throw InputError(where + ": boundary " +
                           std::to_string(e.boundary_id) +
                           " already has a normal constraint or an obstacle.");
        boundary_supports[e.boundary_id] =
          make_function<dim>(e.expressions, 1, constants, where);
      }
    // A boundary takes one kind of normal constraint.
    auto require_unconstrained = [this](const types::boundary_id id,
                                        const std::string       &where) {
      if (normal_displacements.count(id) || obstacles.count(id) ||
          boundary_supports.count(id) || curved_obstacles.count(id) ||
          stops.count(id))
        throw InputError(where + ": boundary " + std::to_string(id) +
                         " already has a normal constraint, an obstacle, a "
                         "boundary support or a stop.");
    };
    for (const BoundaryEntry &e : parse_boundary_list(
           prm.get("Curved obstacles"), dim, false, "Contact/Curved obstacles"))
      {
        const std::string where =
          "Contact/Curved obstacles, boundary " + std::to_string(e.boundary_id);
        require_unconstrained(e.boundary_id, where);
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
        curved_obstacles[e.boundary_id] = std::move(obstacle);
      }
    update_curved_obstacles = prm.get_bool("Update curved obstacles");
    for (const BoundaryEntry &e :
         parse_boundary_list(prm.get("Stops"), dim, false, "Contact/Stops"))
      {
        const std::string where =
          "Contact/Stops, boundary " + std::to_string(e.boundary_id);
        require_unconstrained(e.boundary_id, where);
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

    if (grid_generator == "tunnel_lining")
      {
        if (dim != 2)
          throw InputError("Geometry: tunnel_lining is a 2D grid.");
        if (rotation_degrees != 0 || distortion != 0)
          throw InputError("Geometry: tunnel_lining cannot be rotated or "
                           "distorted (its sections are computed from the "
                           "arcs).");
        lining =
          std::make_shared<const TunnelLining>(grid_arguments, constants);
      }
  }

  namespace
  {
    /**
     * Half model of a cylinder of radius R lying on the plane y = -R: the
     * quarter disk x >= 0, y <= 0, graded towards the contact point (0, -R)
     * by a polar map that keeps the circle exact. Along the surface, half of
     * the nodes lie uniformly on the arc of angle phi_c next to the contact
     * point, the spacing then grows smoothly (quadratic map) up to pi/2; the
     * radius r becomes R (1 - (1 - r/R)^q), which thins the layers towards
     * the surface. Boundary ids: 0 the symmetry plane x = 0, 1 the loaded
     * diameter y = 0, 2 the curved surface.
     */
    void
    half_cylinder(Triangulation<2>  &tria,
                  const std::string &arguments,
                  const unsigned int refinements)
    {
      const auto parts = split_and_trim(arguments, ':');
      if (parts.size() != 3)
        throw InputError(
          "Geometry: half_cylinder takes 'R : phi_c : q' (radius, angle in "
          "radians of the finely meshed arc, radial grading exponent).");
      const double R = std::stod(parts[0]), phi_c = std::stod(parts[1]),
                   q = std::stod(parts[2]);
      if (!(R > 0) || !(phi_c > 0) || !(phi_c <= numbers::PI / 4) || !(q >= 1))
        throw InputError("Geometry: half_cylinder needs R > 0, 0 < phi_c <= "
                         "pi/4 and q >= 1.");
      GridGenerator::quarter_hyper_ball(tria, Point<2>(), R);
      GridTools::transform(
        [](const Point<2> &x) { return Point<2>(x[1], -x[0]); }, tria);
      tria.refine_global(refinements);
      GridTools::transform(
        [R, phi_c, q](const Point<2> &x) {
          const double r = x.norm();
          if (r == 0)
            return x;
          const double phi     = std::atan2(x[0], -x[1]); // from -y towards +x
          const double half_pi = numbers::PI / 2;
          const double t       = std::min(1., std::max(0., phi / half_pi));
          // phi(t) = 2 phi_c t on [0, 1/2]; then the same slope plus a
          // quadratic term reaching pi/2 at t = 1.
          const double c       = (half_pi - 2 * phi_c) / 0.25;
          const double phi_new = (t <= 0.5) ? 2 * phi_c * t :
                                              phi_c + 2 * phi_c * (t - 0.5) +
                                                c * (t - 0.5) * (t - 0.5);
          const double r_new   = R * (1 - std::pow(std::max(0., 1 - r / R), q));
          return Point<2>(r_new * std::sin(phi_new),
                          -r_new * std::cos(phi_new));
        },
        tria);
      tria.reset_all_manifolds();
      tria.set_all_manifold_ids(numbers::flat_manifold_id);
      const double tol = 1e-10 * R;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2> c = cell->face(f)->center();
              cell->face(f)->set_boundary_id(std::abs(c[0]) < tol ? 0 :
                                             std::abs(c[1]) < tol ? 1 :
                                                                    2);
            }
    }

    template <int dim>
    void
    half_cylinder(Triangulation<dim> &, const std::string &, const unsigned int)
    {
      throw InputError("Geometry: half_cylinder is a 2D grid.");
    }
  } // namespace

  template <int dim>
  void
  Scene<dim>::create_mesh(Triangulation<dim> &triangulation) const
  {
    if (lining)
      {
        if constexpr (dim == 2)
          {
            lining->create_coarse_mesh(triangulation);
            triangulation.refine_global(global_refinements);
          }
      }
    else if (grid_generator == "half_cylinder")
      {
        try
          {
            half_cylinder(triangulation, grid_arguments, global_refinements);
          }
        catch (const std::invalid_argument &)
          {
            throw InputError("Geometry: cannot read the half_cylinder "
                             "arguments '" +
                             grid_arguments + "' as 'R : phi_c : q'.");
          }
      }
    else if (grid_generator == "wedge_block")
      {
        // deal.II's subdivided_parallelepiped (not reachable by name):
        // edges a = (L_a, 0) and b = L_b (cos theta, sin theta) from the
        // origin, n_a x n_b cells, colorized: 0 the face along b, 1 its
        // opposite, 2 the face along a, 3 its opposite.
        const auto parts = split_and_trim(grid_arguments, ':');
        if (dim != 2 || parts.size() != 5)
          throw InputError("Geometry: wedge_block is 2D and takes 'L_a : L_b "
                           ": theta (degrees) : n_a : n_b'.");
        double v[5];
        for (unsigned int k = 0; k < 5; ++k)
          v[k] = evaluate_constant_expression(parts[k],
                                              constants,
                                              "Geometry/Grid arguments");
        if (!(v[0] > 0 && v[1] > 0 && v[2] > 0 && v[2] < 180 && v[3] >= 1 &&
              v[4] >= 1))
          throw InputError("Geometry: wedge_block needs L_a, L_b > 0, 0 < "
                           "theta < 180 and at least one cell per edge.");
        if constexpr (dim == 2)
          {
            const double theta = v[2] * numbers::PI / 180.;
            Point<dim>   corners[dim];
            corners[0][0]                  = v[0];
            corners[1][0]                  = v[1] * std::cos(theta);
            corners[1][1]                  = v[1] * std::sin(theta);
            unsigned int subdivisions[dim] = {static_cast<unsigned int>(v[3]),
                                              static_cast<unsigned int>(v[4])};
            GridGenerator::subdivided_parallelepiped<dim>(triangulation,
                                                          subdivisions,
                                                          corners,
                                                          true);
            triangulation.refine_global(global_refinements);
          }
      }
    else
      {
        create_generated_mesh(triangulation);
        triangulation.refine_global(global_refinements);
      }

    if (distortion > 0)
      GridTools::distort_random(distortion, triangulation, true, 20261121);

    if (rotation_degrees != 0)
      {
        const double angle = rotation_degrees * numbers::PI / 180.;
        const double c = std::cos(angle), s = std::sin(angle);
        GridTools::transform(
          [c, s](const Point<dim> &p) {
            Point<dim> q = p;
            q[0]         = c * p[0] - s * p[1];
            q[1]         = s * p[0] + c * p[1];
            return q;
          },
          triangulation);
      }

    // Inverted or degenerate cells (e.g. a rectangle given with its corners
    // swapped) would give a flexibility of the wrong sign: refuse them here.
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!(cell->measure() > 0))
        {
          std::ostringstream s;
          s << "Geometry: the cell with centre (" << cell->center()
            << ") has non-positive measure " << cell->measure()
            << ": the grid arguments describe an impossible (inverted or "
               "degenerate) geometry.";
          throw InputError(s.str());
        }
  }

  template <int dim>
  void
  Scene<dim>::create_generated_mesh(Triangulation<dim> &triangulation) const
  {
    try
      {
        GridGenerator::generate_from_name_and_arguments(triangulation,
                                                        grid_generator,
                                                        grid_arguments);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        throw InputError("Geometry: cannot create the grid '" + grid_generator +
                         "' from the arguments '" + grid_arguments +
                         "': " + Utilities::trim(s.str()));
      }
    catch (const std::exception &e)
      {
        throw InputError("Geometry: cannot create the grid '" + grid_generator +
                         "' from the arguments '" + grid_arguments +
                         "': " + e.what());
      }
    if (triangulation.n_active_cells() == 0)
      throw InputError("Geometry: the grid has no cells.");
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Scene<dim>::strain_from_stress(const SymmetricTensor<2, dim> &sigma) const
  {
    double E = youngs_modulus, nu = poisson_ratio;
    if (dim == 2 && plane_strain)
      {
        E  = youngs_modulus / (1 - poisson_ratio * poisson_ratio);
        nu = poisson_ratio / (1 - poisson_ratio);
      }
    return (1 + nu) / E * sigma -
           nu / E * trace(sigma) * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  double
  Scene<dim>::out_of_plane_stress(const SymmetricTensor<2, dim> &sigma) const
  {
    return (dim == 2 && plane_strain) ? poisson_ratio * trace(sigma) : 0.;
  }

  template <int dim>
  double
  Scene<dim>::nodal_compliance(const Triangulation<dim> &triangulation) const
  {
    double c_h = 1 / youngs_modulus;
    if (dim == 2 && plane_strain)
      c_h *= 1 - poisson_ratio * poisson_ratio;
    if (dim == 3)
      {
        double volume = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          volume += cell->measure();
        c_h /= std::cbrt(volume / triangulation.n_active_cells());
      }
    return c_h;
  }

  template <int dim>
  std::string
  Scene<dim>::plane_condition_name() const
  {
    if (dim == 3)
      return "3D";
    return plane_strain ? "plane strain" : "plane stress";
  }

  template <int dim>
  std::pair<Point<dim>, Tensor<1, dim>>
  Scene<dim>::CurvedObstacle::project(const Point<dim> &x) const
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

  template class Scene<2>;
  template class Scene<3>;
} // namespace hrcontact
