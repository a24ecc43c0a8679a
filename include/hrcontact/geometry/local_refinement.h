#ifndef hrcontact_local_refinement_h
#define hrcontact_local_refinement_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/geometry/mesh_generator.h>

#include <functional>
#include <map>
#include <string>

namespace hrcontact
{
  /**
   * `Mesh refinement/Refinement region` and `Region refinements`: the cells
   * whose centres lie in a box refined again after the global refinements,
   * a given number of times, as a user refines by hand where the answer
   * needs it (near a contact zone, a load). The mesh then has hanging
   * nodes (HangingNodes), which the condensed path imposes.
   */
  template <int dim>
  class LocalRefinement
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    /** Reads the entries, evaluating the box's corners with @p constants. */
    void
    parse_parameters(dealii::ParameterHandler            &prm,
                     const std::map<std::string, double> &constants);

    /** Whether some cells are refined beyond the global refinements. */
    bool
    active() const;

    /**
     * Refine the cells in the box, `Region refinements` times; @p place maps
     * a point of this mesh to where it will end up (a grid that moves its
     * vertices after refinement, MeshGenerator::refined_vertex_map), so that
     * the box is in the final coordinates.
     */
    void
    apply(dealii::Triangulation<dim>                   &triangulation,
          const typename MeshGenerator<dim>::VertexMap &place) const;

    /**
     * Move every hanging vertex to the middle of its parent edge (face): Q1
     * hanging-node constraints interpolate there, so that the fine cells fit
     * their coarse neighbour exactly after a curved manifold or a vertex map
     * put it elsewhere (the patch tests stay exact).
     */
    static void
    centre_hanging_vertices(dealii::Triangulation<dim> &triangulation);

  private:
    unsigned int       n_refinements = 0;
    dealii::Point<dim> lower, upper;
  };
} // namespace hrcontact

#endif
