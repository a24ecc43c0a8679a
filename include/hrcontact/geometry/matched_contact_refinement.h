#ifndef hrcontact_matched_contact_refinement_h
#define hrcontact_matched_contact_refinement_h

#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/geometry/mesh_generator.h>

#include <vector>

namespace hrcontact
{
  /**
   * Keeps the two surfaces of every contact pair equally refined where they
   * face each other on a locally refined mesh: each face of a pair's
   * boundary is refined until its cell is at least as fine (in levels) as
   * the cell of every face opposite on the other boundary: overlapping it
   * along the surface, within the pair's reach across it (where contact
   * may close the gap).
   *
   * Why: both pair methods represent the master surface by its faces'
   * chords. Where the slave's nodes are finer than the master's, the
   * chords' sagitta (h^2 / 8R) moves the slave nodes' gaps by up to that
   * much from node to node, which the stiff contact turns into pressures
   * oscillating by several percent (two cylinders, mortar, the master twice
   * as coarse: +-7 %); where the master is finer, a dual mortar's weighted
   * gap of a node that touches is negative. Meshes that the scene matches
   * across the surface (the two cylinders' equal arcs) stay matched under
   * local and adaptive refinement; meshes that do not keep their ratio.
   */
  template <int dim>
  class MatchedContactRefinement
  {
  public:
    /** A contact pair's boundaries and how far apart its faces may face
     * each other (Contact/Contact pairs' reach; 0: a tenth of the master
     * boundary's bounding box diagonal, as the pair's rows take it). */
    struct Surfaces
    {
      dealii::types::boundary_id slave, master;
      double                     reach = 0;
    };

    explicit MatchedContactRefinement(std::vector<Surfaces> pairs);

    /** Whether there is anything to match. */
    bool
    active() const
    {
      return !pairs.empty();
    }

    /**
     * Refine until no pair face is coarser than a face it overlaps; @p place
     * gives a vertex's final position (MeshGenerator::refined_vertex_map),
     * where the overlap is tested. Collective on a distributed mesh (the
     * faces are gathered from every process). Returns the number of cells
     * refined.
     */
    unsigned int
    apply(dealii::Triangulation<dim>                   &triangulation,
          const typename MeshGenerator<dim>::VertexMap &place) const;

  private:
    std::vector<Surfaces> pairs;
  };
} // namespace hrcontact

#endif
