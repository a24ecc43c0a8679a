#ifndef hrcontact_hexahedron_shape_map_h
#define hrcontact_hexahedron_shape_map_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

namespace hrcontact
{
  class HexahedronEquilibration;

  /**
   * HexahedronEquilibration's cell problem on one shape of parallelepiped,
   * written as what it is: a linear map of the cell's data. The data are
   * d = (u_h at the 8 vertices, the traction of each face in P2 of the
   * face's own coordinates, the body force in P1 of the cell's): 144
   * numbers, against the 1,368 rows and 1,440 unknowns the problem has.
   * Per shape the map's 144 columns are solved once, by the factored
   * (pivoted QR) path, and from them
   *
   * - tau = M d (1,440 x 144, only where tau itself is wanted),
   * - eta_K^2 = |tau - C eps(u_h)|^2_{C^-1,K} = |R d|^2, R the triangular
   *   factor of the residual's values at the cell's rule (no cancellation:
   *   a norm, not a difference of energies),
   * - |sigma_h|^2_{C^-1,K} = s^T G s from sigma_h's 48 vertex values,
   * - the constraints' defect |A M d - c(d)| = |R_D d| likewise,
   *
   * so that a cell costs some 10^4 flops instead of the 4 10^6 of solving
   * it (doc/error-bounds.md, 3D). A similar cell of size h = s h_0 uses the
   * data d^ = (u / s, t, s f).
   *
   * A face's traction and the body force enter through their projections
   * (on a 3 x 3 Gauss rule of the face, and the HR assembly's 2 x 2 x 2
   * rule of the cell: the rules the vertex problems balance the cells
   * with), exact for tractions of degree 2 and linear body forces.
   */
  class HexahedronShapeMap
  {
  public:
    static constexpr unsigned int n_data = 24 + 6 * 3 * 6 + 3 * 4;

    static unsigned int
    u_index(const unsigned int vertex, const unsigned int component)
    {
      return 3 * vertex + component;
    }
    static unsigned int
    traction_index(const unsigned int face,
                   const unsigned int component,
                   const unsigned int basis)
    {
      return 24 + (3 * face + component) * 6 + basis;
    }
    static unsigned int
    force_index(const unsigned int component, const unsigned int basis)
    {
      return 24 + 6 * 3 * 6 + 4 * component + basis;
    }

    /**
     * The map of the shape of the cell of @p vertices, which must be the
     * first cell of its shape @p eq sees (the factors are made on it);
     * @p S the compliance on (xx, yy, zz, xy, xz, yz), engineering shears.
     */
    HexahedronShapeMap(HexahedronEquilibration               &eq,
                       const std::array<dealii::Point<3>, 8> &vertices,
                       const dealii::FullMatrix<double>      &S);

    /** The trilinear hat of unit vertex @p v at @p xi, and its gradient
     * (in the unit cell's coordinates). */
    static double
    hat(const unsigned int          v,
        const dealii::Tensor<1, 3> &xi,
        dealii::Tensor<1, 3>       &gradient);

    /** The size of the cell the map was made on. */
    double h = 1;
    /** Rank of the constraints, their rows and the unknowns. */
    unsigned int rank = 0, n_rows = 0, n_unknowns = 0;

    /** The 9 points of face @p f (deal.II's numbering) at which its
     * traction is sampled for project_traction(). */
    static std::array<dealii::Point<3>, 9>
    face_points(const std::array<dealii::Point<3>, 8> &vertices,
                const unsigned int                     f);
    /** The P2 coefficients of face @p f's traction from its values at
     * face_points(), into d. */
    static void
    project_traction(const std::array<dealii::Tensor<1, 3>, 9> &values,
                     const unsigned int                         f,
                     double                                    *d);
    /** The 8 points at which the body force is sampled. */
    static std::array<dealii::Point<3>, 8>
    cell_points(const std::array<dealii::Point<3>, 8> &vertices);
    /** The P1 coefficients of the body force from its values at
     * cell_points(), into d (times @p scale). */
    static void
    project_body_force(const std::array<dealii::Tensor<1, 3>, 8> &values,
                       const double                               scale,
                       double                                    *d);

    /** eta_K^2 of the cell of the map's size with data @p d. */
    double
    bound_squared(const double *d) const;
    /** |sigma_h|^2_{C^-1} on the cell of the map's size, from sigma_h's
     * vertex values (6 components each, vertex by vertex). */
    double
    stress_energy(const std::array<double, 48> &s) const;
    /** The Euclidean norm of the constraints' defect of tau = M d (a bound
     * of its largest entry), in the rows' units on the map's cell. */
    double
    defect(const double *d) const;
    /** tau's coefficients (HexahedronEquilibration's layout). */
    void
    coefficients(const double *d, dealii::Vector<double> &x) const;

  private:
    struct UnitStrainStress;
    /** The problems of the 144 data columns: tau (X) and A x - c. */
    void
    solve_columns(HexahedronEquilibration               &eq,
                  const std::array<dealii::Point<3>, 8> &vertices,
                  const UnitStrainStress                &elastic_stress,
                  std::vector<dealii::Vector<double>>   &X,
                  std::vector<dealii::Vector<double>>   &defects);
    /** R from the residual tau - C eps(u_h) of each column at the cell's
     * rule, and G. */
    void
    factor_residual(HexahedronEquilibration                   &eq,
                    const dealii::FullMatrix<double>          &S,
                    const UnitStrainStress                    &elastic_stress,
                    const std::vector<dealii::Vector<double>> &X);
    /** M, column-major (n_unknowns x n_data). */
    std::vector<double> M;
    /** The residual's triangular factor (n_data x n_data, column-major)
     * and its column pivots. */
    std::vector<double> R;
    std::vector<int>    pivots;
    /** sigma_h's energy on the vertex values. */
    dealii::FullMatrix<double> G;
    /** The same for the constraints' defect A M d - c(d). */
    std::vector<double> R_defect;
    std::vector<int>    pivots_defect;
  };
} // namespace hrcontact

#endif
