#ifndef hrcontact_cell_equilibration_h
#define hrcontact_cell_equilibration_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/adaptivity/block_null_space.h>
#include <hrcontact/adaptivity/constrained_least_squares.h>
#include <hrcontact/adaptivity/face_tractions.h>
#include <hrcontact/adaptivity/triangle_split.h>

#include <array>
#include <map>
#include <set>
#include <vector>

namespace hrcontact
{
  /**
   * Step 2 of EquilibratedStress: on each cell, split at its centre into
   * triangles (TriangleSplit), the symmetric stress, polynomial of `degree` on
   * each, with div tau + f = 0 on each triangle (against the polynomials of
   * degree p - 1), tau n equal to the FaceTractions on the cell's faces and
   * continuous across the inner edges (against the polynomials of degree p
   * on each edge), that minimises the cell's share of the bound |tau - C
   * eps(u_h)|_{C^-1}. The split is why one exists: at a corner two faces
   * meet whose tractions one symmetric polynomial could not match there.
   * The constraints and the energy depend on the cell's shape only: their
   * factors (SVD of the constraints, null space, reduced Hessian) are kept
   * per shape and body and reused, scaled, by every translated and scaled
   * copy (the refinement levels of a locally refined mesh). A shape met for
   * the first time that is not a parallelogram (every cell of a curved
   * mesh) is solved once, directly (ConstrainedLeastSquares), at a tenth
   * of the flops; its factors are kept when it comes again.
   */
  class CellEquilibration
  {
  public:
    /** Degree 3 gives the same bounds to 1 % at twice the cost. */
    static constexpr unsigned int degree = 2;

    CellEquilibration(const Results<2> &results, const FaceTractions &faces);

    /** One cell: @p x the coefficients; this cell's eta_K^2 and
     * |sigma_h|^2_{C^-1, K}. */
    void
    solve(const dealii::DoFHandler<2>::active_cell_iterator &cell,
          dealii::Vector<double>                            &x,
          double                                            &bound_squared,
          double                                            &energy_squared);

    const TrianglePolynomials polynomials;
    /** The largest residual of the constraints, relative to max |sigma_h|
     * h_K: the part of the data (tractions, body force) outside the range
     * of the constraint matrix, which no admissible field can meet. */
    double residual = 0;

  private:
    struct Factors
    {
      /** x = M_c c + M_g g: M_g = N (N^T H N)^{-1} N^T, M_c = A^+ - M_g H
       * A^+, with N the null space of A and H the energy's Hessian. */
      dealii::FullMatrix<double> M_c, M_g;
      /** The size of the cell they were computed on. */
      double h = 1;
      /** The monomials of degree p and p - 1 at the rule's points (rows). */
      dealii::FullMatrix<double> values, lower_values;
      /** The left null space U_0 of the constraint matrix A: A x - c =
       * -U_0 U_0^T c. */
      dealii::FullMatrix<double> left_null;
      /** Parallelograms: M_g G, G taking the linear strain's coefficients
       * to g, and the inverse of the basis (1, xi, eta) at three of the
       * rule's points that fits them. */
      dealii::FullMatrix<double>  M_g_G, fit;
      std::array<unsigned int, 3> fit_points{};
    };
    /** The shape up to translation and scale (with its hanging nodes),
     * and the body. */
    std::vector<long long>
    shape_key(const TriangleSplit       &split,
              dealii::types::material_id body) const;
    /** The monomials at the rule's points (F.values, F.lower_values). */
    void
    tabulate(const TriangleSplit                 &split,
             const std::vector<dealii::Point<2>> &points,
             Factors                             &F) const;
    /** The energy's Hessian H = sum_q w_q B_q^T S B_q. */
    void
    hessian(const Factors                   &F,
            const dealii::types::material_id body,
            const std::vector<double>       &weights,
            const unsigned int               n_triangles,
            dealii::FullMatrix<double>      &H);
    /** g = sum_q w_q B_q^T e_q, e the strain (or, for a nonlinear law, the
     * S-strain of the target stress): the energy's linear term. */
    void
    energy_gradient(const Factors                   &F,
                    const dealii::types::material_id body,
                    const bool                       nonlinear,
                    const unsigned int               n_triangles,
                    dealii::Vector<double>          &g) const;
    /** A shape met once: x from the constraints and the energy of this
     * cell, and the residual |A x - c|. */
    void
    solve_directly(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                   const TriangleSplit                               &split,
                   const dealii::types::material_id                   body,
                   const bool                                         nonlinear,
                   dealii::Vector<double>                            &x);
    /** This cell's eta_K^2 and |sigma_h|^2 from the coefficients @p x. */
    void
    finish(const dealii::DoFHandler<2>::active_cell_iterator &cell,
           const MaterialLaw<2>                              &law,
           const Factors                                     &F,
           const dealii::Vector<double>                      &x,
           double                                            &bound_squared,
           double                                            &energy_squared);
    const Factors &
    factors(const TriangleSplit                 &split,
            const dealii::types::material_id     body,
            const std::vector<dealii::Point<2>> &points,
            const std::vector<double>           &weights);
    /** The compliance on the stress components and its inverse, per body. */
    const std::pair<dealii::FullMatrix<double>, dealii::FullMatrix<double>> &
    compliances(const dealii::types::material_id body);
    void
    constraint_matrix(const TriangleSplit                 &split,
                      const std::vector<dealii::Point<2>> &points,
                      const std::vector<double>           &weights,
                      dealii::FullMatrix<double>          &A) const;
    void
    constraint_data(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                    const TriangleSplit                               &split,
                    const std::vector<dealii::Point<2>>               &points,
                    const std::vector<double>                         &weights,
                    const Factors                                     &F,
                    dealii::Vector<double>                            &c) const;

    const Results<2>                         &results;
    const FaceTractions                      &faces;
    const TrianglePolynomials                 lower;
    CellSampler                               sampler;
    std::map<std::vector<long long>, Factors> cache;
    /** Shapes met once (solved directly); a second meeting keeps factors. */
    std::set<std::vector<long long>> seen;
    /** The direct path's tables, matrices and factorisation. */
    Factors                       direct, low;
    std::vector<dealii::Point<2>> low_points;
    std::vector<double>           low_weights;
    dealii::FullMatrix<double>    A_direct, H_direct;
    /** The direct path's solve, triangle by triangle first. */
    BlockNullSpace block_solve;
    std::map<dealii::types::material_id,
             std::pair<dealii::FullMatrix<double>, dealii::FullMatrix<double>>>
           compliance;
    double sigma_max = 0;
    /** Scratch of solve(), kept to spare the allocations per cell. */
    std::vector<dealii::Point<2>>              points;
    std::vector<double>                        weights;
    std::vector<dealii::SymmetricTensor<2, 2>> eps, sigma_h;
    /** A nonlinear law: the stress of u_h's strain, W'(eps(u_h)), per
     * point. */
    std::vector<dealii::SymmetricTensor<2, 2>> target;
    dealii::Vector<double>                     c, g, xg, Ax;
    /**
     * A nonlinear law's share of the bound: eta_K^2 = 2 int [phi^c(tau) +
     * W(eps(u_h)) - tau : eps(u_h)] (the Fenchel-Young gap, W(eps) =
     * s : eps - phi^c(s) at s = W'(eps)), and 2 int phi^c(sigma_h).
     */
    void
    fenchel_young(const MaterialLaw<2>         &law,
                  const Factors                &F,
                  const dealii::Vector<double> &x,
                  double                       &bound_squared,
                  double                       &energy_squared) const;
    /** The constraints' rows on a split. */
    unsigned int
    n_rows(const TriangleSplit &split) const;
  };
} // namespace hrcontact

#endif
