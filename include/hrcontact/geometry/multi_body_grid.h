#ifndef hrcontact_multi_body_grid_h
#define hrcontact_multi_body_grid_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <hrcontact/core/input.h>
#include <hrcontact/geometry/body_placement.h>
#include <hrcontact/geometry/mesh_generator.h>
#include <hrcontact/material/material_law.h>

#include <memory>
#include <vector>

namespace hrcontact
{
  /**
   * Several bodies in one mesh (issue 19): body 1 is the Geometry
   * section's grid, bodies 2..4 come from the subsections "Bodies/Body k",
   * each from its own grid generator, mirrored, rotated about the origin
   * and shifted.
   * On a distributed mesh, where every body's grid has a coarse mesh
   * (MeshGenerator::create_coarse), the bodies' coarse meshes are placed
   * and joined, their manifolds carried along (MovedManifold), and the
   * joined mesh is refined: each process keeps only its part. Otherwise
   * each body is generated and refined on its own (with its own manifolds),
   * flattened, placed, and the refined bodies are joined. Either way the
   * bodies' vertices are not merged:
   * bodies that touch share positions but no nodes, and interact only
   * through contact pairs. Cells carry their body's index (0, 1, ...) as
   * material id; body k's boundary ids are its generator's plus its offset
   * (default 10 (k - 1)), so that the bodies' faces stay apart.
   */
  template <int dim>
  class MultiBodyGrid : public MeshGenerator<dim>
  {
  public:
    /** The largest number of bodies a scene may have. */
    static constexpr unsigned int max_bodies = 4;

    /** Bodies/Number of bodies and the subsections Body 2 ... Body 4. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** One body besides the first. */
    struct Body
    {
      std::shared_ptr<const MeshGenerator<dim>> grid;
      BodyPlacement<dim>                        placement;
      unsigned int                              boundary_id_offset = 0;
      /** Its own material, or null: the scene's (Material). */
      std::shared_ptr<const MaterialLaw<dim>> material;
    };

    /**
     * The bodies the parameters describe after the first (empty: one body,
     * the scene is as before).
     */
    static std::vector<Body>
    parse_bodies(dealii::ParameterHandler &prm, const Constants &constants);

    MultiBodyGrid(std::shared_ptr<const MeshGenerator<dim>> first,
                  std::vector<Body>                         others);

    void
    create(dealii::Triangulation<dim> &triangulation,
           const unsigned int          refinements) const override;

    /**
     * The bodies' coarse meshes placed and joined, their manifolds carried
     * along; false where a body's grid has none or one of its manifolds
     * cannot be moved.
     */
    bool
    create_coarse(dealii::Triangulation<dim> &triangulation) const override;

    /** Each body's own map, in its own frame: placed, mapped, placed back. */
    typename MeshGenerator<dim>::VertexMap
    refined_vertex_map() const override;

    unsigned int
    n_bodies() const;

    /** Each body's names, shifted by its offset, as "body k: name". */
    std::map<dealii::types::boundary_id, std::string>
    boundary_names() const override;

  private:
    /** Body b's grid, placement (identity for the first) and offset. */
    const MeshGenerator<dim> &
    grid_of(const unsigned int b) const;
    BodyPlacement<dim>
    placement_of(const unsigned int b) const;

    /**
     * The distributed variant: create_coarse, refined, vertices moved, and
     * flat as the joined refined bodies; false (nothing done) where
     * create_coarse cannot.
     */
    bool
    create_from_coarse_meshes(dealii::Triangulation<dim> &triangulation,
                              const unsigned int          refinements) const;

    std::shared_ptr<const MeshGenerator<dim>> first;
    std::vector<Body>                         others;
  };
} // namespace hrcontact

#endif
