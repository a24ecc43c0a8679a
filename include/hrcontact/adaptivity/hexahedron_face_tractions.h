#ifndef hrcontact_hexahedron_face_tractions_h
#define hrcontact_hexahedron_face_tractions_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>

#include <hrcontact/adaptivity/vertex_problems.h>
#include <hrcontact/core/results.h>

#include <array>
#include <map>
#include <vector>

namespace hrcontact
{
  /**
   * Bilinear face tractions that balance every cell of a 3D conforming mesh
   * of parallelepipeds (step 1 of EquilibratedStress in 3D; FaceTractions
   * is the 2D one, with hanging nodes and contact). As in 2D: around each
   * vertex v the cells' residuals R_K = int_K sigma_h : eps(phi_v e_c) - f_c
   * phi_v (less their loaded faces' data moments) sum to zero where v is
   * not held (the HR equations, on the HR assembly's own rule), and per
   * vertex and component the moments b_F = int_F t phi_v of the faces
   * through v solve A b = R (+1 on the face's owner, -1 on its other side),
   * the solution closest to the averaged sigma_h n. A face's four moments
   * give its bilinear traction (the inverse of its mass matrix), and since
   * the hats sum to one and reproduce linear fields each cell's tractions
   * balance its body force in force and moment.
   */
  class HexahedronFaceTractions
  {
  public:
    struct Face
    {
      unsigned int                         owner = 0;
      std::array<unsigned int, 4>          vertices{};
      std::array<std::array<double, 3>, 4> moment{}, value{};
      std::array<bool, 3>                  known{};
      bool                                 boundary    = false;
      dealii::types::boundary_id           boundary_id = 0;
    };

    explicit HexahedronFaceTractions(const Results<3> &results);

    /** The traction cell @p cell sees at @p x of its face @p face (by the
     * mesh's face index; outward normal @p normal): the data on a loaded
     * face, else the bilinear traction, its sign flipped on the side that
     * does not own it. */
    dealii::Tensor<1, 3>
    traction(const unsigned int          face,
             const unsigned int          cell,
             const dealii::Point<3>     &x,
             const dealii::Tensor<1, 3> &normal) const;

    /** The largest residual of the vertex problems, relative to the
     * largest cell residual: round-off when the HR equations hold. */
    double residual = 0;

  private:
    const Results<3>                                 &results;
    std::vector<bool>                                 usable;
    std::vector<Face>                                 faces;
    std::vector<std::array<std::array<double, 3>, 8>> cell_residual;
    std::vector<std::array<std::array<double, 3>, 4>> average;
    double                                            scale = 0;
    /** A^+ of a vertex problem's +-1 matrix, kept per sign pattern. */
    VertexProblemInverses pseudo_inverse;

    void
    classify_faces();
    /** R_K, the loaded faces' data moments and the averaged sigma_h n. */
    void
    cell_residuals();
    void
    solve_vertex_problems();
    void
    solve_vertex(
      const unsigned int                                                 vertex,
      const std::vector<dealii::Triangulation<3>::active_cell_iterator> &cells);
    /** The face's coordinates (a, b) of @p x (x = p0 + a (p1 - p0) + b (p2 -
     * p0), p the face's vertices). */
    std::array<double, 2>
    face_coordinates(const Face &face, const dealii::Point<3> &x) const;
  };
} // namespace hrcontact

#endif
