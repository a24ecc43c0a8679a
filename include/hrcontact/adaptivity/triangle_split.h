#ifndef hrcontact_triangle_split_h
#define hrcontact_triangle_split_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/core/results.h>

#include <array>
#include <map>
#include <vector>

namespace hrcontact
{
  /** The compliance of a law on the stress components (MixedSpaces'
   * order: xx, yy, xy; xx, yy, zz, xy, xz, yz), engineering shear strains:
   * tau : C^-1 tau = t^T S t (2D and 3D). */
  template <int dim>
  dealii::FullMatrix<double>
  component_compliance(const MaterialLaw<dim> &law);

  /**
   * A 2D cell split at its centre into triangles, on which the equilibrated
   * stress is a polynomial per triangle (EquilibratedStress): one triangle
   * per boundary segment, i.e. four, plus one for each face whose neighbour
   * is refined (its hanging node splits the face into the neighbours' two
   * faces, whose tractions differ). The boundary points counter-clockwise
   * (the last repeats the first), the segment (an active line of the mesh)
   * under each edge, the centre, the length that scales the local
   * coordinates, and a rule on the triangles.
   */
  struct TriangleSplit
  {
    explicit TriangleSplit(
      const dealii::Triangulation<2>::active_cell_iterator &cell);

    /** The cell's vertices counter-clockwise (deal.II's 0, 1, 3, 2), and
     * the cell's face between corner k and corner k + 1. */
    static constexpr unsigned int corner[4]          = {0, 1, 3, 2};
    static constexpr unsigned int face_under_edge[4] = {2, 1, 3, 0};

    std::vector<dealii::Point<2>> P;
    /** The line index of the segment under edge P_k P_{k+1}. */
    std::vector<unsigned int> segment;
    /** Bit f: face f is split by a hanging node. */
    unsigned int     split_faces = 0;
    dealii::Point<2> centre;
    double           h = 1;

    /** The number of triangles (and of boundary segments). */
    unsigned int
    n_triangles() const
    {
      return segment.size();
    }

    /** Whether the opposite sides are parallel (the Q1 map affine). */
    bool
    parallelogram() const;

    /** Duffy's collapse of an n x n Gauss rule on each triangle (exact to
     * degree 2n - 2); triangle k's points start at k n^2. */
    void
    rule(const unsigned int             n,
         std::vector<dealii::Point<2>> &points,
         std::vector<double>           &weights) const;
  };

  /**
   * Symmetric polynomial stresses on the triangles of a split: per triangle and
   * component (xx, yy, xy) the monomials xi^a eta^b, a + b <= p, of the
   * local coordinates xi = (x - centre) / h.
   */
  struct TrianglePolynomials
  {
    explicit TrianglePolynomials(const unsigned int degree);

    unsigned int                             degree;
    std::vector<std::array<unsigned int, 2>> monomials;

    /** The unknown of triangle k, component c, monomial m. */
    unsigned int
    index(const unsigned int k,
          const unsigned int c,
          const unsigned int m) const
    {
      return (k * 3 + c) * monomials.size() + m;
    }
    unsigned int
    n_unknowns(const unsigned int n_triangles) const
    {
      return 3 * n_triangles * monomials.size();
    }
    double
    value(const TriangleSplit    &split,
          const dealii::Point<2> &x,
          const unsigned int      m) const;
    dealii::Tensor<1, 2>
    gradient(const TriangleSplit    &split,
             const dealii::Point<2> &x,
             const unsigned int      m) const;
    /** The stress of coefficients @p x on triangle @p k at @p point. */
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::Vector<double> &x,
           const TriangleSplit          &split,
           const unsigned int            k,
           const dealii::Point<2>       &point) const;
  };

  /**
   * eps(u_h) and sigma_h at real points of a cell. On a parallelogram the
   * affine map takes a rule on the triangles to the same unit points on
   * every cell, so the shape functions there are tabulated once per rule;
   * other cells find their unit points by the Q1 mapping's Newton
   * iteration (deal.II's batched transform_points_real_to_unit_cell).
   * (FEValues, set up per cell for its own points, would cost more than the
   * rest of the bound.)
   */
  class CellSampler
  {
  public:
    explicit CellSampler(const Results<2> &results);

    void
    operator()(const dealii::DoFHandler<2>::active_cell_iterator &cell,
               const TriangleSplit                               &split,
               const std::vector<dealii::Point<2>>               &points,
               std::vector<dealii::SymmetricTensor<2, 2>>        &eps,
               std::vector<dealii::SymmetricTensor<2, 2>>        &sigma);

  private:
    struct Table
    {
      std::vector<dealii::Point<2>>                  unit;
      std::vector<std::vector<dealii::Tensor<1, 2>>> u_grad, hat_grad;
      std::vector<std::vector<double>>               s_value;
    };
    void
    tabulate(Table &t) const;
    /** Whether every shape function of both elements lies in Q1 on the
     * unit cell (Q1 displacements; DGQ1 and Pian-Sumihara stresses): then
     * each is its vertex values times the bilinear hats, evaluated in
     * closed form rather than through the elements' polynomial classes. */
    bool in_q1 = false;
    /** The shape functions' values at the four unit vertices. */
    std::vector<std::array<double, 4>> u_vertex, s_vertex;

    const Results<2>                            &results;
    const dealii::FiniteElement<2>              &fe_u, &fe_s;
    std::vector<dealii::types::global_dof_index> u_dofs, s_dofs;
    std::vector<double>                          u_values, s_values;
    std::vector<unsigned int>                    u_component;
    std::vector<dealii::SymmetricTensor<2, 2>>   s_tensor;
    /** Per number of points and split faces. */
    std::map<std::pair<unsigned int, unsigned int>, Table> tables;
    Table                                                  own;
  };
} // namespace hrcontact

#endif
