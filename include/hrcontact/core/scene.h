#ifndef hrcontact_scene_h
#define hrcontact_scene_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/input.h>
#include <hrcontact/geometry/tunnel_lining.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * What a run computes on: the mesh, the linear elastic material, the loads
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

    /** Build the mesh, refine, distort and rotate it as asked. */
    void
    create_mesh(dealii::Triangulation<dim> &triangulation) const;

    /** A deal.II GridGenerator grid by name and arguments, unrefined. */
    void
    create_generated_mesh(dealii::Triangulation<dim> &triangulation) const;

    /** Compliance E^{-1}: strain from stress (plane strain uses E', nu'). */
    dealii::SymmetricTensor<2, dim>
    strain_from_stress(const dealii::SymmetricTensor<2, dim> &sigma) const;

    /** The out-of-plane stress: nu (sxx + syy) in plane strain, else 0. */
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, dim> &sigma) const;

    /**
     * The nodal compliance c_h that scales the initial penalty: (1 - nu^2)/E
     * in plane strain, 1/E in plane stress, 1/(E h) in 3D with h the mean
     * cell size.
     */
    double
    nodal_compliance(const dealii::Triangulation<dim> &triangulation) const;

    /** Human-readable description of the 2D assumption ("3D" in 3D). */
    std::string
    plane_condition_name() const;

    Constants constants;

    // Geometry
    std::string grid_generator;
    /** The tunnel_lining geometry when the scene uses it, else null. */
    std::shared_ptr<const TunnelLining> lining;
    std::string                         grid_arguments;
    unsigned int                        global_refinements = 0;
    double                              distortion         = 0;
    double                              rotation_degrees   = 0;

    // Material
    double youngs_modulus = 1;
    double poisson_ratio  = 0;
    bool   plane_strain   = true;

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

    // Supports
    struct PrescribedDisplacement
    {
      std::vector<unsigned int>                    components;
      std::unique_ptr<dealii::FunctionParser<dim>> values; // one per component
    };
    std::map<dealii::types::boundary_id, PrescribedDisplacement>
      prescribed_displacements;
    /** Bilateral "u.n = g" constraints: the Q rows of eq. 38. */
    std::map<dealii::types::boundary_id,
             std::unique_ptr<dealii::FunctionParser<dim>>>
      normal_displacements;

    /**
     * Rigid straight obstacles (a line in 2D, a plane in 3D) acting on the
     * nodes of a boundary id: a point of the obstacle and its unit normal
     * pointing into the obstacle. Nodal gap g = (x0 - x) . n (eq. 10, 35).
     */
    struct Obstacle
    {
      dealii::Point<dim>     point;
      dealii::Tensor<1, dim> normal;
    };
    std::map<dealii::types::boundary_id, Obstacle> obstacles;
    /**
     * Unilateral frictionless supports along the body's own boundary (the
     * surrounding medium taken rigid): per boundary id the initial gap g; the
     * normal of each node is the body's outward normal there (face normals
     * averaged), pointing into the support.
     */
    std::map<dealii::types::boundary_id,
             std::unique_ptr<dealii::FunctionParser<dim>>>
      boundary_supports;

    /**
     * Two-sided stops with limit reactions (section 2.4.2) on the nodes of a
     * boundary id: the direction d of w = u.d and the functions g-, g+, p0-,
     * p0+ and, optionally, k-, k+ of the node position (null: k = 0).
     */
    struct Stop
    {
      dealii::Tensor<1, dim>                       direction;
      std::unique_ptr<dealii::FunctionParser<dim>> values[6];
    };
    std::map<dealii::types::boundary_id, Stop> stops;

    /**
     * Rigid curved obstacles on the nodes of a boundary id: a circle (a
     * cylinder in 3D: its axis along z) or sphere of centre c and radius R,
     * or the region phi < 0 of a level-set expression. The body stays in
     * phi >= 0.
     */
    struct CurvedObstacle
    {
      enum class Shape
      {
        circle,
        sphere,
        level_set
      };
      Shape                                        shape = Shape::circle;
      dealii::Point<dim>                           centre;
      double                                       radius = 0;
      std::unique_ptr<dealii::FunctionParser<dim>> phi;

      /**
       * The point of the obstacle's surface nearest to x (exact for a
       * circle or sphere; for a level set, the iteration x <- x - phi
       * grad phi / |grad phi|^2, which ends on the surface and is the
       * nearest point when phi is a distance), and the unit normal there
       * pointing into the obstacle (-grad phi / |grad phi|).
       */
      std::pair<dealii::Point<dim>, dealii::Tensor<1, dim>>
      project(const dealii::Point<dim> &x) const;
    };
    std::map<dealii::types::boundary_id, CurvedObstacle> curved_obstacles;
    /**
     * Re-linearise the curved obstacles at the current configuration after
     * every multiplier update (condensed path), rather than once at the
     * initial one.
     */
    bool update_curved_obstacles = true;
  };
} // namespace hrcontact

#endif
