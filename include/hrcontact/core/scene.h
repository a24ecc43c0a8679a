#ifndef hrcontact_scene_h
#define hrcontact_scene_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/adaptivity/adaptive_refinement.h>
#include <hrcontact/constraints/constraint_source.h>
#include <hrcontact/core/input.h>
#include <hrcontact/geometry/local_refinement.h>
#include <hrcontact/geometry/matched_contact_refinement.h>
#include <hrcontact/geometry/mesh_generator.h>
#include <hrcontact/geometry/tunnel_lining.h>
#include <hrcontact/material/material_law.h>
#include <hrcontact/material/stress_constraint.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * What a run computes on: the mesh, the material law, the loads
   * and the supports, all read from the parameter file. A scene configures
   * only what it names: an empty list means "none of these".
   */
  template <int dim>
  class Scene
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** The contact pairs' surfaces, kept equally refined where they face
     * each other on a locally refined mesh. */
    MatchedContactRefinement<dim>
    matched_contact_refinement() const;

    /** Build the mesh, refine, distort and rotate it as asked. */
    void
    create_mesh(dealii::Triangulation<dim> &triangulation) const;

    /** The out-of-plane stress of a body's material (0 in plane stress,
     * 3D); `body` is the cell's material id. */
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &sigma,
                        const dealii::types::material_id       body = 0) const;

    /** The law of a body (a cell's material id): its own (Bodies/Body k/
     * Own material) or the scene's. */
    const MaterialLaw<dim> &
    material_of(const dealii::types::material_id body) const;

    /** Whether every body's law is linear. */
    bool
    all_linear() const;

    /** The largest nodal compliance of the bodies' laws on this mesh (the
     * penalty scale of the augmented Lagrangian). */
    double
    nodal_compliance(const dealii::Triangulation<dim> &triangulation) const;

    /** Whether the bodies have laws of their own. */
    bool
    has_body_materials() const;

    /** Human-readable description of the 2D assumption ("3D" in 3D). */
    std::string
    plane_condition_name() const;

    Constants constants;

    // Geometry
    std::string grid_generator;
    /** The grid generator Geometry/Grid generator names. */
    std::shared_ptr<const MeshGenerator<dim>> grid;
    /** The tunnel_lining geometry when the scene uses it, else null. */
    std::shared_ptr<const TunnelLining> lining;
    std::string                         grid_arguments;
    unsigned int                        global_refinements = 0;
    double                              distortion         = 0;
    double                              rotation_degrees   = 0;
    /** Mesh refinement/: cells refined again in a box (hanging nodes). */
    LocalRefinement<dim> local_refinement;
    /** Mesh refinement/: the adaptive cycles, and the steps of those so
     * far that this run's mesh replays. */
    AdaptiveRefinement<dim> adaptive;
    /** Whether the mesh is not uniformly refined (hanging nodes). */
    bool
    refined_locally() const
    {
      return local_refinement.active() || adaptive.active();
    }

    /** The material law (Material/Model), read with the scene. */
    std::shared_ptr<const MaterialLaw<dim>> material;
    /** By body (material id): a law of its own, or null for the scene's
     * `material`; empty for a scene of one body. */
    std::vector<std::shared_ptr<const MaterialLaw<dim>>> body_materials;
    /** The number of bodies (Bodies/Number of bodies). */
    unsigned int n_bodies = 1;
    /** The cone of admissible stresses (Material/Admissible stresses), or
     * null: any stress. */
    std::shared_ptr<const StressConstraint<dim>> stress_constraint;

    // Loads
    std::unique_ptr<dealii::FunctionParser<dim>> body_force;
    std::map<dealii::types::boundary_id,
             std::unique_ptr<dealii::FunctionParser<dim>>>
      tractions;
    /**
     * Earth-pressure-like loads per boundary id: pressures p_k acting on the
     * projection of the surface normal to axis k, i.e. the traction
     * t_k = -p_k n_k (no sum) with n the outward normal. Equal p_k give a
     * normal pressure; a vertical p_y alone loads the horizontal projection,
     * as soil loads on a tunnel do.
     */
    std::map<dealii::types::boundary_id,
             std::unique_ptr<dealii::FunctionParser<dim>>>
      projected_pressures;

    /**
     * The boundary constraint kinds the scene uses (prescribed
     * displacements, normal displacements, obstacles, boundary supports,
     * curved obstacles, stops, ...), in their registered order.
     */
    std::vector<std::shared_ptr<ConstraintSource<dim>>> constraints;

    /** Whether some constraint kind changes its rows during the solve. */
    bool
    has_changing_rows() const;
  };
} // namespace hrcontact

#endif
