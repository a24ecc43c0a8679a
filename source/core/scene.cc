#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/distributed/tria_base.h>

#include <hrcontact/constraints/contact_pairs.h>
#include <hrcontact/core/scene.h>
#include <hrcontact/geometry/multi_body_grid.h>
#include <hrcontact/geometry/tunnel_lining_grid.h>

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

    LocalRefinement<dim>::declare_parameters(prm);
    AdaptiveRefinement<dim>::declare_parameters(prm);
    MaterialLawFactory<dim>::declare_parameters(prm);
    StressConstraintFactory<dim>::declare_parameters(prm);

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

    ConstraintSources<dim>::declare_parameters(prm);
    MultiBodyGrid<dim>::declare_parameters(prm);
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
    local_refinement.parse_parameters(prm, constants);
    adaptive.parse_parameters(prm);
    if (refined_locally() && distortion != 0)
      throw InputError("Geometry/Distortion with Mesh refinement (Region "
                       "refinements or Adaptive cycles): a distortion would "
                       "move the hanging nodes off their parents' edges; use "
                       "one or the other.");

    material          = MaterialLawFactory<dim>::create(prm, constants);
    stress_constraint = StressConstraintFactory<dim>::create(prm);

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

    constraints             = ConstraintSources<dim>::create(prm, constants);
    grid                    = MeshGeneratorFactory<dim>::create(grid_generator,
                                             grid_arguments,
                                             constants);
    const std::string fixed = grid->fixed_geometry_reason();
    if (!fixed.empty() && (rotation_degrees != 0 || distortion != 0))
      throw InputError("Geometry: " + fixed + ".");
    if (const auto *tunnel =
          dynamic_cast<const TunnelLiningGrid<dim> *>(grid.get()))
      lining = tunnel->lining();

    // Further bodies: the mesh joins them, each keeps its material.
    auto bodies = MultiBodyGrid<dim>::parse_bodies(prm, constants);
    n_bodies    = 1 + bodies.size();
    body_materials.clear();
    if (!bodies.empty())
      {
        if (lining)
          throw InputError("Bodies: the tunnel_lining grid is a scene of "
                           "one body.");
        body_materials.push_back(nullptr);
        for (const auto &body : bodies)
          body_materials.push_back(body.material);
        grid = std::make_shared<MultiBodyGrid<dim>>(grid, std::move(bodies));
      }
  }

  template <int dim>
  const MaterialLaw<dim> &
  Scene<dim>::material_of(const types::material_id body) const
  {
    if (body < body_materials.size() && body_materials[body])
      return *body_materials[body];
    return *material;
  }

  template <int dim>
  bool
  Scene<dim>::has_body_materials() const
  {
    for (const auto &m : body_materials)
      if (m)
        return true;
    return false;
  }

  template <int dim>
  bool
  Scene<dim>::all_linear() const
  {
    for (const auto &m : body_materials)
      if (m && !m->is_linear())
        return false;
    return material->is_linear();
  }

  template <int dim>
  double
  Scene<dim>::nodal_compliance(const Triangulation<dim> &triangulation) const
  {
    double c = material->nodal_compliance(triangulation);
    for (const auto &m : body_materials)
      if (m)
        c = std::max(c, m->nodal_compliance(triangulation));
    return c;
  }

  template <int dim>
  MatchedContactRefinement<dim>
  Scene<dim>::matched_contact_refinement() const
  {
    std::vector<typename MatchedContactRefinement<dim>::Surfaces> surfaces;
    for (const auto &source : constraints)
      if (const auto *pairs =
            dynamic_cast<const ContactPairs<dim> *>(source.get()))
        for (const auto &p : pairs->pair_list())
          surfaces.push_back({p.slave, p.master, p.reach});
    return MatchedContactRefinement<dim>(surfaces);
  }

  template <int dim>
  void
  Scene<dim>::create_mesh(Triangulation<dim> &triangulation) const
  {
    if (!refined_locally())
      grid->create(triangulation, global_refinements);
    else if (grid->create_coarse(triangulation))
      {
        // Refined where the grid refines (its manifolds), then moved as
        // the grid moves its refined vertices.
        triangulation.refine_global(global_refinements);
        const auto place = grid->refined_vertex_map();
        local_refinement.apply(triangulation, place);
        adaptive.apply(triangulation, global_refinements);
        matched_contact_refinement().apply(triangulation, place);
        MeshGenerator<dim>::move_refined_vertices(triangulation, place);
        LocalRefinement<dim>::centre_hanging_vertices(triangulation);
      }
    else
      {
        grid->create(triangulation, global_refinements);
        const auto place = [](const Point<dim> &x, const types::material_id) {
          return x;
        };
        local_refinement.apply(triangulation, place);
        adaptive.apply(triangulation, global_refinements);
        matched_contact_refinement().apply(triangulation, place);
        LocalRefinement<dim>::centre_hanging_vertices(triangulation);
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
    // A distributed mesh: each process checks its own cells, and every
    // process stops if one found such a cell (not only that one, or the
    // others would wait for it).
    std::string error;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && !(cell->measure() > 0))
        {
          std::ostringstream s;
          s << "Geometry: the cell with centre (" << cell->center()
            << ") has non-positive measure " << cell->measure()
            << ": the grid arguments describe an impossible (inverted or "
               "degenerate) geometry.";
          error = s.str();
          break;
        }
    if (const auto *parallel_mesh =
          dynamic_cast<const parallel::TriangulationBase<dim> *>(
            &triangulation))
      for (const auto &e :
           Utilities::MPI::all_gather(parallel_mesh->get_communicator(), error))
        if (error.empty())
          error = e;
    if (!error.empty())
      throw InputError(error);
  }

  template <int dim>
  double
  Scene<dim>::out_of_plane_stress(const SymmetricTensor<2, dim> &sigma,
                                  const types::material_id       body) const
  {
    return material_of(body).out_of_plane_stress(sigma);
  }

  template <int dim>
  std::string
  Scene<dim>::plane_condition_name() const
  {
    return material->plane_condition_name();
  }

  template <int dim>
  bool
  Scene<dim>::has_changing_rows() const
  {
    for (const auto &source : constraints)
      if (source->changes_rows())
        return true;
    return false;
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace hrcontact
