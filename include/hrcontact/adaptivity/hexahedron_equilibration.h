#ifndef hrcontact_hexahedron_equilibration_h
#define hrcontact_hexahedron_equilibration_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/adaptivity/shape_factors.h>

#include <array>
#include <functional>
#include <map>
#include <vector>

namespace hrcontact
{
  /**
   * The 3D cell problem of the error bound (step 2 of EquilibratedStress
   * on a hexahedron): the cell split into 24 tetrahedra (its centre, the
   * centres of its faces and their edges), on each a symmetric stress
   * polynomial of degree 2 (60 coefficients, 1,440 a cell), with div tau + f
   * = 0 on each tetrahedron (against the linear polynomials), tau n equal
   * to the given tractions on the 24 outer triangles and continuous across
   * the 36 inner ones (against the quadratics on each triangle); of the
   * admissible fields the one nearest C eps(u_h) in the compliance. As in
   * 2D the split is what makes one exist: along an edge of the cell two
   * faces meet whose tractions one symmetric polynomial could not match.
   * The constraints and the energy depend on the shape only: their
   * factorisation is kept per shape and reused by translated and scaled
   * copies (1,368 x 1,440: a second or two per shape, so meshes of
   * parallelepipeds, one shape per refinement level and body).
   */
  class HexahedronEquilibration
  {
  public:
    static constexpr unsigned int degree = 2;
    /** Tetrahedra, and unknowns per tetrahedron (6 components). */
    static constexpr unsigned int n_tetrahedra = 24;

    /** The traction of cell face f (deal.II's numbering) at a point. */
    using Traction =
      std::function<dealii::Tensor<1, 3>(unsigned int,
                                         const dealii::Point<3> &)>;
    using VectorField =
      std::function<dealii::Tensor<1, 3>(const dealii::Point<3> &)>;
    /** The stress tau is compared with (C eps(u_h)), at a point. */
    using StressField =
      std::function<dealii::SymmetricTensor<2, 3>(const dealii::Point<3> &)>;

    /** @p S: the compliance on the components (xx, yy, zz, xy, xz, yz),
     * engineering shear strains. */
    explicit HexahedronEquilibration(const dealii::FullMatrix<double> &S);

    /**
     * The cell of @p vertices (deal.II's order): the coefficients @p x and
     * |tau - target|^2_{C^-1, K}. @p body_force may be empty (zero).
     */
    double
    solve(const std::array<dealii::Point<3>, 8> &vertices,
          const Traction                        &traction,
          const VectorField                     &body_force,
          const StressField                     &target,
          dealii::Vector<double>                &x);

    /** One cell's data for a batched solve (data()). */
    struct CellData
    {
      /** The shape's factors (opaque), the cell's size over theirs. */
      const void *shape = nullptr;
      double      s     = 1;
      /** The constraints' data and the energy's linear term, scaled to the
       * shape's first cell. */
      dealii::Vector<double> c0, g0;
      /** The target stress at the rule's points, tetrahedron by
       * tetrahedron. */
      std::vector<dealii::SymmetricTensor<2, 3>> targets;
    };
    /** Sets the cell of @p vertices, finds or factors its shape, and
     * computes its data. */
    void
    data(const std::array<dealii::Point<3>, 8> &vertices,
         const Traction                        &traction,
         const VectorField                     &body_force,
         const StressField                     &target,
         CellData                              &cell);
    /**
     * The coefficients of the cells of @p batch together: per shape, one
     * matrix product for all its cells (its factors, some 30 MB, streamed
     * from memory once rather than once a cell), and the constraints'
     * largest defect per cell, in its own units (@p residuals); each
     * cell's A x - c into @p defects if given.
     */
    void
    solve(const std::vector<const CellData *> &batch,
          std::vector<dealii::Vector<double>> &x,
          std::vector<double>                 &residuals,
          std::vector<dealii::Vector<double>> *defects = nullptr);

    /** The shape of @p vertices up to translation and scale (the key the
     * factors are kept by). */
    static std::vector<long long>
    shape_key(const std::array<dealii::Point<3>, 8> &vertices);
    /** |tau - target|^2_{C^-1} on the cell set last (set_cell()), the
     * target at the rule's points as data() kept it. */
    double
    distance(const dealii::Vector<double>                     &x,
             const std::vector<dealii::SymmetricTensor<2, 3>> &targets) const;

    /** Sets the cell (solve() does it too). */
    void
    set_cell(const std::array<dealii::Point<3>, 8> &vertices);
    /** The rule of tetrahedron @p k of the cell (exact to degree 5). */
    void
    tetrahedron_rule(const unsigned int             k,
                     std::vector<dealii::Point<3>> &points,
                     std::vector<double>           &weights) const;

    /** tau of coefficients @p x on tetrahedron @p k of the last solved
     * cell at @p point. */
    dealii::SymmetricTensor<2, 3>
    stress(const dealii::Vector<double> &x,
           const unsigned int            k,
           const dealii::Point<3>       &point) const;

    /** The largest entry of A x - c of the last solve, in the rows' units
     * (a stress times an area): what of the data no admissible field met. */
    double residual = 0;
    /** Rank and size of the constraints of the last shape factored. */
    unsigned int rank = 0, n_rows = 0, n_unknowns = 0;

  private:
    struct Geometry
    {
      /** 0-7 the vertices, 8-13 the face centres, 14 the centre. */
      std::array<dealii::Point<3>, 15> P;
      double                           h = 1;
    };
    /** Tetrahedron k: (centre, face centre, two vertices of an edge of the
     * face); its face without the centre is on the cell's boundary. */
    std::array<std::array<unsigned int, 4>, n_tetrahedra> tets;
    std::array<unsigned int, n_tetrahedra>                face_of_tet;
    /** Inner triangles: the two tetrahedra and the three points. */
    struct InnerFace
    {
      unsigned int                a, b;
      std::array<unsigned int, 3> points;
    };
    std::vector<InnerFace>                         inner;
    dealii::FullMatrix<double>                     S;
    Geometry                                       geometry;
    std::map<std::vector<long long>, ShapeFactors> shapes;

    unsigned int
    index(const unsigned int k,
          const unsigned int c,
          const unsigned int m) const
    {
      return (k * 6 + c) * monomials.size() + m;
    }
    std::vector<std::array<unsigned int, 3>> monomials, lower;
    dealii::Tensor<1, 3>
    monomial_gradient(const std::array<unsigned int, 3> &e,
                      const dealii::Point<3>            &x) const;
    /** The rows (A) and data (c) of the constraints; A only if asked. */
    void
    constraints(const Traction             &traction,
                const VectorField          &body_force,
                dealii::FullMatrix<double> *A,
                dealii::Vector<double>     &c);
    void
    energy(const StressField                          &target,
           dealii::FullMatrix<double>                 *H,
           dealii::Vector<double>                     &g,
           std::vector<dealii::SymmetricTensor<2, 3>> &targets) const;
    /** The monomials of exponents @p exps at @p x (all at once). */
    void
    monomial_values(const dealii::Point<3>                         &x,
                    const std::vector<std::array<unsigned int, 3>> &exps,
                    double *values) const;
  };
} // namespace hrcontact

#endif
