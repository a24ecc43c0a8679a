#ifndef hrcontact_equilibrium_reduction_h
#define hrcontact_equilibrium_reduction_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/equilibrium_system.h>

#include <ostream>
#include <vector>

namespace hrcontact
{
  /**
   * The paper's equilibrium reduction (section 4.2-4.3, eq. 39-43, 50-51),
   * the one piece of custom linear algebra the method demands: deal.II has no
   * null-space basis of a rectangular equilibrium operator.
   *
   * Gaussian reduction with partial pivoting of C^T (LAPACK dgetrf on the
   * tau x n matrix) picks n stress columns s1 with C1 square and invertible:
   * P C^T = [L11; L21] U, C1 = (L11 U)^T, C0 = (L21 U)^T, hence
   * C1^{-1} C0 = L11^{-T} L21^T =: X (U cancels; |L| <= 1 keeps X tame).
   * With s = R s0 + t, R = [I; -X], t = [0; C1^{-1} f], every s0 gives a
   * stress in equilibrium with f on the free rows, and the complementary
   * energy becomes a dense concave quadratic in s0 with Hessian
   * -R^T F R (eq. 45). A vanishing pivot means C has a zero-energy mode (a
   * mechanism, an unsupported body or a stress space too poor for the mesh):
   * initialize() then throws an InputError that names the nodes the mode
   * moves.
   *
   * Dense: memory ~ 8 (tau n + n m + 2 m^2) bytes with m = tau - n, work
   * ~ 2 n m^2 + m^3/3 flops. It serves small and medium meshes and is the
   * reference for the condensed path.
   */
  class EquilibriumReduction
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Factorise, select s1, form X, t, R^T F R, Q R. */
    void
    initialize(const EquilibriumSystem &system, std::ostream *log = nullptr);

    unsigned int
    n_free_rows() const
    {
      return n;
    }
    unsigned int
    n_stresses() const
    {
      return tau;
    }
    /** dim(s0) = tau - rank(C) (= tau - n when C has full row rank). */
    unsigned int
    n_self_equilibrated() const
    {
      return m;
    }

    /** s = R s0 (no particular part). */
    void
    apply_R(const dealii::Vector<double> &s0, dealii::Vector<double> &s) const;
    /** The particular stress t of eq. 41: C t = f, zero on s0. */
    const dealii::Vector<double> &
    particular_stress() const
    {
      return t;
    }

    /**
     * Displacements from the stresses (eq. 50-51): C1^T u_C = (F s - Q^T w -
     * H^T u-hat)_1, with w the normal displacements of the Q rows (one per
     * contact row) and u-hat the prescribed values. Returns one value per
     * rotated row.
     */
    std::vector<double>
    row_displacements(const dealii::Vector<double> &s,
                      const std::vector<double>    &contact_w) const;

    /** @name Pieces of the reduced functional (eq. 44-47) for the contact
     * solver. */
    /** @{ */
    /** Number of Q rows (contact constraints, unilateral or bilateral). */
    unsigned int
    n_contact_rows() const
    {
      return n_q;
    }
    /** Row i of Q R (length m), eq. 42. */
    const double *
    QR_row(const unsigned int i) const
    {
      return QR.data() + static_cast<std::size_t>(i) * m;
    }
    /** a = Q t - q, eq. 42: p = Q R s0 + a. */
    const std::vector<double> &
    contact_offset() const
    {
      return a;
    }
    /** b0 = R^T (-F t + H^T u-hat + Q^T g): the linear term in s0. */
    const dealii::Vector<double> &
    linear_term() const
    {
      return b0;
    }
    /** y = M0 x with M0 = R^T F R. */
    void
    multiply_M0(const dealii::Vector<double> &x,
                dealii::Vector<double>       &y) const;
    /**
     * The cells' F_c in the system changed (a material's state): compute
     * M0 = R^T F R, its Cholesky factor and b0 again. The Gaussian reduction
     * of C, R, Q R and a do not depend on F and stay.
     */
    void
    flexibility_changed();
    /** x <- M0^{-1} x (Cholesky factor kept from initialize()). */
    void
    solve_M0(double *x, const unsigned int n_rhs = 1) const;
    /** s = R s0 + t. */
    void
    stress_from_s0(const dealii::Vector<double> &s0,
                   dealii::Vector<double>       &s) const;
    /** @} */

    /** Nodal displacements of eq. 50-51 (row_displacements, unrotated). */
    void
    system_displacements(const dealii::Vector<double> &s,
                         const std::vector<double>    &contact_w,
                         dealii::Vector<double>       &u) const
    {
      system->displacements_from_row_values(row_displacements(s, contact_w), u);
    }

    double pivot_tolerance = 1e-9;

  private:
    unsigned int           n_q = 0;
    std::vector<double>    QR;
    std::vector<double>    a;
    dealii::Vector<double> b0;

    const EquilibriumSystem *system = nullptr;
    unsigned int             tau = 0, n = 0, m = 0;

    /** perm[i], i < n: stress dof of the i-th s1 entry; i >= n: of s0. */
    std::vector<unsigned int> perm;
    /** position of each stress dof in perm. */
    std::vector<unsigned int> position;
    /** L11 (unit lower) and U of P C^T, n x n, column-major. */
    std::vector<double> LU11;
    /** X = C1^{-1} C0, n x m, column-major. */
    std::vector<double>    X;
    dealii::Vector<double> t;
    /** Cholesky factor of R^T F R, m x m, column-major (lower). */
    std::vector<double> M0_factor;
  };
} // namespace hrcontact

#endif
