#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <deal.II/distributed/tria.h>

#include <hrcontact/geometry/multi_body_grid.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  MultiBodyGrid<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Bodies");
    {
      prm.declare_entry(
        "Number of bodies",
        "1",
        Patterns::Integer(1, max_bodies),
        "How many bodies the scene has. Body 1 is the Geometry section's "
        "grid with the Material section's law; bodies 2.." +
          std::to_string(max_bodies) +
          " are described in the subsections 'Body 2', ... . The bodies "
          "share no nodes: they interact through Contact/Contact pairs.");
      for (unsigned int k = 2; k <= max_bodies; ++k)
        {
          prm.enter_subsection("Body " + std::to_string(k));
          prm.declare_entry("Grid generator",
                            "hyper_cube",
                            Patterns::Anything(),
                            "The body's grid, as Geometry/Grid generator.");
          prm.declare_entry("Grid arguments",
                            "0 : 1 : true",
                            Patterns::Anything(),
                            "Its arguments, as Geometry/Grid arguments.");
          prm.declare_entry(
            "Mirror",
            "none",
            Patterns::Selection("none|x|y|z"),
            "Mirror the body in a coordinate (x: x -> -x, the plane x = 0) "
            "before the rotation and the shift, e.g. y to turn the lower "
            "half of a half_cylinder into an upper half.");
          prm.declare_entry(
            "Rotation angle",
            "0",
            Patterns::Anything(),
            "Rotate the body about the origin (about z in 3D) by this angle "
            "in degrees (an expression of the constants), before the shift.");
          prm.declare_entry("Shift",
                            "",
                            Patterns::Anything(),
                            "Translate the body by this vector, components "
                            "separated by ',' (expressions of the "
                            "constants). Empty: none.");
          prm.declare_entry(
            "Boundary id offset",
            std::to_string(10 * (k - 1)),
            Patterns::Integer(0, 200),
            "Added to every boundary id of the body's grid, so that the "
            "bodies' boundaries can be told apart (body k: 10 (k - 1) by "
            "default, e.g. a colorized rectangle's top face is 3 + 10 on "
            "body 2).");
          prm.declare_entry(
            "Own material",
            "false",
            Patterns::Bool(),
            "Whether the body has its own material law (the subsection "
            "Material here, as the top-level Material section); false: the "
            "scene's.");
          MaterialLawFactory<dim>::declare_parameters(prm);
          prm.leave_subsection();
        }
    }
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<typename MultiBodyGrid<dim>::Body>
  MultiBodyGrid<dim>::parse_bodies(ParameterHandler &prm,
                                   const Constants  &constants)
  {
    std::vector<Body> bodies;
    prm.enter_subsection("Bodies");
    const unsigned int n = prm.get_integer("Number of bodies");
    for (unsigned int k = 2; k <= n; ++k)
      {
        const std::string where = "Bodies/Body " + std::to_string(k);
        prm.enter_subsection("Body " + std::to_string(k));
        Body body;
        body.grid = MeshGeneratorFactory<dim>::create(Utilities::trim(prm.get(
                                                        "Grid generator")),
                                                      prm.get("Grid arguments"),
                                                      constants);
        if (!body.grid->fixed_geometry_reason().empty())
          throw InputError(where + ": " + body.grid->fixed_geometry_reason() +
                           ".");
        body.placement.rotation_degrees =
          evaluate_constant_expression(prm.get("Rotation angle"),
                                       constants,
                                       where + "/Rotation angle");
        const std::string shift = Utilities::trim(prm.get("Shift"));
        if (!shift.empty())
          {
            const auto parts = split_and_trim(shift, ',');
            if (parts.size() != dim)
              throw InputError(
                where + "/Shift: expected " + std::to_string(dim) +
                " components separated by ',' in '" + shift + "'.");
            for (unsigned int d = 0; d < dim; ++d)
              body.placement.shift[d] =
                evaluate_constant_expression(parts[d],
                                             constants,
                                             where + "/Shift");
          }
        body.boundary_id_offset  = prm.get_integer("Boundary id offset");
        const std::string mirror = prm.get("Mirror");
        body.placement.mirror    = mirror == "none" ? -1 : mirror[0] - 'x';
        if (body.placement.mirror >= static_cast<int>(dim))
          throw InputError(where + "/Mirror: a " + std::to_string(dim) +
                           "D body has no coordinate " + mirror + ".");
        if (prm.get_bool("Own material"))
          body.material = MaterialLawFactory<dim>::create(prm, constants);
        prm.leave_subsection();
        bodies.push_back(std::move(body));
      }
    prm.leave_subsection();
    return bodies;
  }

  template <int dim>
  MultiBodyGrid<dim>::MultiBodyGrid(
    std::shared_ptr<const MeshGenerator<dim>> first,
    std::vector<Body>                         others)
    : first(std::move(first))
    , others(std::move(others))
  {}

  template <int dim>
  unsigned int
  MultiBodyGrid<dim>::n_bodies() const
  {
    return 1 + others.size();
  }

  template <int dim>
  std::map<types::boundary_id, std::string>
  MultiBodyGrid<dim>::boundary_names() const
  {
    std::map<types::boundary_id, std::string> names;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      for (const auto &[id, name] : grid_of(b).boundary_names())
        names[id + (b == 0 ? 0 : others[b - 1].boundary_id_offset)] =
          "body " + std::to_string(b + 1) + ": " + name;
    return names;
  }

  template <int dim>
  const MeshGenerator<dim> &
  MultiBodyGrid<dim>::grid_of(const unsigned int b) const
  {
    return b == 0 ? *first : *others[b - 1].grid;
  }

  template <int dim>
  BodyPlacement<dim>
  MultiBodyGrid<dim>::placement_of(const unsigned int b) const
  {
    return b == 0 ? BodyPlacement<dim>() : others[b - 1].placement;
  }

  namespace
  {
    /**
     * The coarse description of several bodies: each body's cells, faces
     * and vertices appended with its material id (the body), its boundary
     * ids shifted, and mirrored cells turned right again.
     */
    template <int dim>
    struct JoinedDescription
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      SubCellData                faces;
      /** Boundary ids by body, to refuse two bodies with the same id. */
      std::vector<std::set<types::boundary_id>> ids;

      /** Append `body`, already placed; manifold ids through `manifold`. */
      void
      append(const Triangulation<dim>                               &body,
             const unsigned int                                      b,
             const unsigned int                                      offset,
             const bool                                              mirrored,
             const std::map<types::manifold_id, types::manifold_id> &manifold)
      {
        auto map_manifold = [&manifold](const types::manifold_id id) {
          const auto it = manifold.find(id);
          return it == manifold.end() ? numbers::flat_manifold_id : it->second;
        };
        auto [v, c, sub] = GridTools::get_coarse_mesh_description(body);
        const unsigned int first_vertex = vertices.size();
        vertices.insert(vertices.end(), v.begin(), v.end());
        for (auto &cell : c)
          {
            for (auto &i : cell.vertices)
              i += first_vertex;
            // A mirror image is inside out: exchange the first two
            // reference directions to turn it right again (a reversal of
            // one direction would also reverse the lines along it, which
            // then disagree with their neighbours' on refinement).
            if (mirrored)
              for (unsigned int v = 1; v < cell.vertices.size(); v += 4)
                std::swap(cell.vertices[v], cell.vertices[v + 1]);
            cell.material_id = b;
            cell.manifold_id = map_manifold(cell.manifold_id);
            cells.push_back(cell);
          }
        ids.resize(b + 1);
        auto shift_ids = [&](auto &list, auto &target, const bool of_cells) {
          for (auto &face : list)
            {
              for (auto &i : face.vertices)
                i += first_vertex;
              face.manifold_id = map_manifold(face.manifold_id);
              if (face.boundary_id != numbers::internal_face_boundary_id)
                {
                  const unsigned int id = face.boundary_id + offset;
                  if (id >= numbers::internal_face_boundary_id)
                    throw InputError(
                      "Bodies/Body " + std::to_string(b + 1) +
                      ": boundary id " + std::to_string(face.boundary_id) +
                      " plus the offset " + std::to_string(offset) +
                      " is not a valid boundary id.");
                  face.boundary_id = id;
                  if (of_cells)
                    ids[b].insert(id);
                }
              target.push_back(face);
            }
        };
        shift_ids(sub.boundary_lines, faces.boundary_lines, dim == 2);
        shift_ids(sub.boundary_quads, faces.boundary_quads, dim == 3);
        for (unsigned int a = 0; a < b; ++a)
          for (const auto id : ids[b])
            if (ids[a].count(id))
              throw InputError(
                "Bodies/Body " + std::to_string(b + 1) + ": boundary id " +
                std::to_string(id) + " is also one of body " +
                std::to_string(a + 1) +
                "'s; give the body a different Boundary id offset.");
      }
    };
  } // namespace

  template <int dim>
  void
  MultiBodyGrid<dim>::create(Triangulation<dim> &triangulation,
                             const unsigned int  refinements) const
  {
    if (dynamic_cast<parallel::distributed::Triangulation<dim> *>(
          &triangulation) &&
        create_from_coarse_meshes(triangulation, refinements))
      return;

    JoinedDescription<dim> joined;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      {
        // Generated and refined alone (its manifolds place the new
        // vertices), then flattened: the joined mesh is one level.
        Triangulation<dim> body, flat;
        grid_of(b).create(body, refinements);
        GridGenerator::flatten_triangulation(body, flat);
        const BodyPlacement<dim> placement = placement_of(b);
        if (b > 0)
          GridTools::transform(placement, flat);
        joined.append(flat,
                      b,
                      b == 0 ? 0 : others[b - 1].boundary_id_offset,
                      placement.mirrors(),
                      {});
      }
    triangulation.create_triangulation(joined.vertices,
                                       joined.cells,
                                       joined.faces);
  }

  template <int dim>
  bool
  MultiBodyGrid<dim>::create_coarse(Triangulation<dim> &triangulation) const
  {
    JoinedDescription<dim> joined;
    // The bodies' manifolds, moved, under new ids (body b's id i becomes
    // 1000 b + i + 1, clear of the flat manifold id).
    std::vector<std::pair<types::manifold_id, std::unique_ptr<Manifold<dim>>>>
      manifolds;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      {
        Triangulation<dim> body;
        if (!grid_of(b).create_coarse(body))
          return false;
        const BodyPlacement<dim> placement = placement_of(b);
        std::map<types::manifold_id, types::manifold_id> manifold_ids;
        for (const types::manifold_id id : body.get_manifold_ids())
          if (id != numbers::flat_manifold_id)
            {
              const Manifold<dim> &manifold = body.get_manifold(id);
              // Manifolds that hold their own triangulation cannot move to
              // another one.
              if (dynamic_cast<const TransfiniteInterpolationManifold<dim> *>(
                    &manifold))
                return false;
              if (dynamic_cast<const FlatManifold<dim> *>(&manifold))
                continue;
              manifold_ids[id] = 1000 * b + id + 1;
              manifolds.emplace_back(
                1000 * b + id + 1,
                std::make_unique<MovedManifold<dim>>(manifold, placement));
            }
        GridTools::transform(placement, body);
        joined.append(body,
                      b,
                      b == 0 ? 0 : others[b - 1].boundary_id_offset,
                      placement.mirrors(),
                      manifold_ids);
      }
    triangulation.create_triangulation(joined.vertices,
                                       joined.cells,
                                       joined.faces);
    for (const auto &[id, manifold] : manifolds)
      triangulation.set_manifold(id, *manifold);
    return true;
  }

  template <int dim>
  typename MeshGenerator<dim>::VertexMap
  MultiBodyGrid<dim>::refined_vertex_map() const
  {
    std::vector<typename MeshGenerator<dim>::VertexMap> maps;
    std::vector<BodyPlacement<dim>>                     placements;
    for (unsigned int b = 0; b < n_bodies(); ++b)
      {
        maps.push_back(grid_of(b).refined_vertex_map());
        placements.push_back(placement_of(b));
      }
    return [maps, placements](const Point<dim> &x, const types::material_id b) {
      AssertIndexRange(b, maps.size());
      return placements[b](maps[b](placements[b].inverse(x), 0));
    };
  }

  template <int dim>
  bool
  MultiBodyGrid<dim>::create_from_coarse_meshes(
    Triangulation<dim> &triangulation,
    const unsigned int  refinements) const
  {
    if (!create_coarse(triangulation))
      return false;
    triangulation.refine_global(refinements);
    this->move_refined_vertices(triangulation, refined_vertex_map());
    // As the joined refined bodies: flat, the manifolds placed the points.
    triangulation.reset_all_manifolds();
    triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
    return true;
  }

  template class MultiBodyGrid<2>;
  template class MultiBodyGrid<3>;
} // namespace hrcontact
