#ifndef hrcontact_mesh_generator_h
#define hrcontact_mesh_generator_h

#include <deal.II/grid/tria.h>

#include <hrcontact/core/input.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * A grid by name (Geometry/Grid generator) from its arguments (Geometry/
   * Grid arguments). Our own generators register themselves with
   * HRCONTACT_REGISTER_MESH_GENERATOR; any other name is handed to deal.II's
   * GridGenerator::generate_from_name_and_arguments. A generator is
   * constructed from (arguments, constants) when the scene is read; it may
   * check its arguments then or when it creates the mesh.
   */
  template <int dim>
  class MeshGenerator
  {
  public:
    virtual ~MeshGenerator() = default;

    /** The coarse mesh, refined `refinements` times. */
    virtual void
    create(dealii::Triangulation<dim> &triangulation,
           const unsigned int          refinements) const = 0;

    /**
     * The coarse mesh with the manifolds its refinement needs, where the
     * grid can be built in three steps: create(t, r) places the same
     * vertices as create_coarse(t), t.refine_global(r) and then
     * move_refined_vertices(t, refined_vertex_map()). Returns false (the
     * default) when the grid cannot: a locally refined mesh then puts its
     * new vertices on straight edges.
     */
    virtual bool
    create_coarse(dealii::Triangulation<dim> &triangulation) const;

    /** Where a vertex x of a cell of body (material id) b goes. */
    using VertexMap =
      std::function<dealii::Point<dim>(const dealii::Point<dim>        &x,
                                       const dealii::types::material_id b)>;

    /**
     * Where a vertex of the refined coarse mesh goes (default: it stays).
     * The body matters where several bodies, each with its own map, share
     * one mesh (MultiBodyGrid).
     */
    virtual VertexMap
    refined_vertex_map() const;

    /** Move every vertex once by @p map, with the body of a cell holding it
     * (bodies share no vertices). */
    static void
    move_refined_vertices(dealii::Triangulation<dim> &triangulation,
                          const VertexMap            &map);

    /**
     * Why this grid may not be distorted or rotated afterwards (empty: it
     * may), for the error message.
     */
    virtual std::string
    fixed_geometry_reason() const;
    /**
     * What the grid's boundary ids are (e.g. 2: "curved surface"), for the
     * message when a `.prm` entry names an id the mesh does not have; empty
     * (the default) where the grid does not say.
     */
    virtual std::map<dealii::types::boundary_id, std::string>
    boundary_names() const;
  };

  /** The name -> factory registry of MeshGenerator. */
  template <int dim>
  class MeshGeneratorFactory
  {
  public:
    using Factory = std::function<
      std::unique_ptr<MeshGenerator<dim>>(const std::string &arguments,
                                          const Constants   &constants)>;

    static bool
    register_generator(const std::string &name, const Factory &factory);

    /** The generator of that name, its arguments parsed; deal.II's for a
     * name not registered here. */
    static std::unique_ptr<MeshGenerator<dim>>
    create(const std::string &name,
           const std::string &arguments,
           const Constants   &constants);

  private:
    static std::vector<std::pair<std::string, Factory>> &
    registry();
  };
} // namespace hrcontact

/** Register CLASSNAME<2> and CLASSNAME<3> as grid NAME; the class has a
 * constructor taking (arguments, constants). */
#define HRCONTACT_REGISTER_MESH_GENERATOR(classname, name)             \
  namespace                                                            \
  {                                                                    \
    const bool classname##_registered_2d =                             \
      ::hrcontact::MeshGeneratorFactory<2>::register_generator(        \
        name,                                                          \
        [](const std::string &arguments, const Constants &constants) { \
          return std::make_unique<classname<2>>(arguments, constants); \
        });                                                            \
    const bool classname##_registered_3d =                             \
      ::hrcontact::MeshGeneratorFactory<3>::register_generator(        \
        name,                                                          \
        [](const std::string &arguments, const Constants &constants) { \
          return std::make_unique<classname<3>>(arguments, constants); \
        });                                                            \
  }

#endif
