#ifndef hrcontact_tunnel_lining_h
#define hrcontact_tunnel_lining_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/grid/tria.h>

#include <hrcontact/core/input.h>

#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * A section across a curved or straight bar: the line through `point` in
   * the direction `across` (from the inner to the outer face), and the
   * mid-line coordinate `s` at which it sits. The mid-line tangent is
   * `across` turned by -90 degrees, so that for a lining described
   * clockwise (crown towards invert, right half) the tangent points along
   * increasing s.
   */
  struct SectionStation
  {
    dealii::Point<2>     point;
    dealii::Tensor<1, 2> across;
    double               s = 0;
    std::string          part;
  };

  /**
   * The half section (x >= 0) of a tunnel lining made of two circular arcs,
   * the paper's first example (section 5, Fig. 10). The paper gives the radii,
   * the width, the height and the two thicknesses; what closes the geometry
   * is ours and stated here and in doc/tunnel.md:
   * - the radii, width and height are those of the intrados (the clear
   *   section); the crown arc of radius R_c is centred at the origin, on the
   *   springline, so the clear width is 2 R_c (11.10 m for R_c = 5.55 m);
   * - the invert arc of radius R_i is centred on the axis x = 0 such that
   *   the clear height (crown top to invert bottom) is H; the two intrados
   *   arcs meet where the circles cross, below the springline;
   * - the extrados arcs are concentric with the intrados ones, offset by the
   *   crown thickness t_c and the invert thickness t_i; the thickness
   *   changes along the straight line joining the intrados and extrados
   *   joints.
   *
   * Boundary ids: 0 intrados, 1 extrados, 2 symmetry cut at the crown top,
   * 3 symmetry cut at the invert bottom. The mesh is built from these numbers
   * with SphericalManifold arcs and a TransfiniteInterpolationManifold inside,
   * so refinement stays on the circles.
   */
  class TunnelLining
  {
  public:
    /**
     * Arguments 'R_c : R_i : H : t_c : t_i [: cells across]', each an
     * expression of the constants. Impossible geometries (arcs that do not
     * meet below the springline, thickness too large) are input errors.
     */
    TunnelLining(const std::string &arguments, const Constants &constants);

    /** The coarse mesh (near-square cells) with manifolds attached. */
    void
    create_coarse_mesh(dealii::Triangulation<2> &triangulation) const;

    /**
     * About n section stations along the mid-line, equally spaced in arc
     * length: radial sections of the crown and of the invert, skipping the
     * short stretch around the joint where a radial line would cut both
     * arcs (its width is reported by joint_gap_length()).
     */
    std::vector<SectionStation>
    sections(const unsigned int n) const;

    /**
     * Arc length along the extrados from the crown top to the boundary point
     * x (its projection on the extrados arcs).
     */
    double
    extrados_arc_length(const dealii::Point<2> &x) const;

    /** Total length of the extrados of the half section. */
    double
    extrados_length() const;

    /** Length of the mid-line stretch without stations around the joint. */
    double
    joint_gap_length() const;

    /** One line per dimension derived here, for logs and docs. */
    std::string
    describe() const;

    double       R_c, R_i, H, t_c, t_i;
    unsigned int cells_across = 1;

    /** Invert centre (0, y_invert); crown centre is the origin. */
    double y_invert;
    /** Joints: angles from the crown centre (theta) and invert centre (phi). */
    double           theta_in, theta_out, phi_in, phi_out;
    dealii::Point<2> joint_in, joint_out;
  };
} // namespace hrcontact

#endif
