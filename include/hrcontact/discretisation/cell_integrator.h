#ifndef hrcontact_cell_integrator_h
#define hrcontact_cell_integrator_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <memory>
#include <utility>
#include <vector>

namespace hrcontact
{
  template <int dim>
  class StressConstraintField;
  template <int dim>
  class GaussPointCone;

  /**
   * One cell's Hellinger-Reissner blocks (section 4.2), term by term: the
   * compliance F_c = int psi C psi (eq. 35), the equilibrium B_c = int
   * eps(phi) : psi, the loads f_c of body force and tractions, a nonlinear
   * law's strain term e_c at a stress state, and a stress constraint's
   * augmented Lagrangian term at its points. Q1 x DGQ1 products are
   * integrated exactly on parallelograms by 2 Gauss points per direction.
   * With an assumed-stress element the blocks are integrated in the value
   * element and reduced by T_c. Cells are integrated in mesh order: a
   * translation of the previous cell of a homogeneous, stress-independent
   * material keeps its F_c and B_c (deal.II's CellSimilarity).
   */
  template <int dim>
  class CellIntegrator
  {
  public:
    /** @p stress_state: the stresses the material is evaluated at (null:
     * zero); @p constraint_field: a stress constraint's state, or null;
     * @p cone: a stress constraint imposed in closed form at the Gauss
     * points, whose strain state is then @p stress_state, or null. */
    CellIntegrator(const Scene<dim>                 &scene,
                   const MixedSpaces<dim>           &spaces,
                   const FieldVector                *stress_state,
                   const StressConstraintField<dim> *constraint_field,
                   const GaussPointCone<dim>        *cone = nullptr);

    using cell_iterator =
      typename dealii::DoFHandler<dim>::active_cell_iterator;

    /** The blocks of the cell @p cu of the displacement space and @p cs,
     * the same cell of the stress unknowns' space. */
    const CellBlocks &
    integrate(const cell_iterator &cu, const cell_iterator &cs);

  private:
    /** The stress state's value dofs on the cell (s_loc), and T_c. */
    void
    read_stress_state(const cell_iterator &cs);
    /** F_c, B_c, the strain term and the body force, point by point; only
     * the body force on a cell that keeps the previous blocks. */
    void
    volume_terms(const cell_iterator    &cu,
                 const MaterialLaw<dim> &material,
                 const bool              same,
                 const bool              strain_term);
    /** F_c += int psi_i psi_j K(c_i, c_j) at point q. */
    void
    compliance_term(const unsigned int q, const double JxW);
    /** The Newton model of the Gauss-point cone at point q: K = F_q, and
     * d_c += int psi e_q (GaussPointCone::model). */
    void
    cone_term(const unsigned int q, const double JxW, const cell_iterator &cu);
    /** B_c += int eps(phi_i) : psi_j at point q. */
    void
    equilibrium_term(const unsigned int q, const double JxW);
    /** f_c += int phi_i b at point q. */
    void
    body_force_term(const unsigned int q, const double JxW);
    /** The stress constraint's term at its points: strain P(X) and
     * compliance alpha DP(X), X = mu + alpha sigma. */
    void
    constraint_term(const cell_iterator &cs);
    /** f_c += int phi_i t on the faces with a traction or a projected
     * pressure. */
    void
    traction_terms(const cell_iterator &cu);
    /** A load that is not finite is an input error. */
    void
    check_loads(const cell_iterator &cu) const;
    /** The blocks of an assumed-stress element: B_c T_c, T_c^T F_c T_c,
     * T_c^T d_c. */
    void
    reduce_to_parameters(const bool same);

    const Scene<dim>                 &scene;
    const MixedSpaces<dim>           &spaces;
    const FieldVector                *stress_state;
    const StressConstraintField<dim> *constraint_field;
    const GaussPointCone<dim>        *cone;
    static constexpr unsigned int     n_comp =
      MixedSpaces<dim>::n_stress_components;
    const bool                    parameters;
    const unsigned int            n_p;
    const dealii::QGauss<dim>     quadrature;
    const dealii::QGauss<dim - 1> face_quadrature;
    dealii::FEValues<dim>         fv_u, fv_s;
    dealii::FEFaceValues<dim>     fv_face;
    const unsigned int            n_u, n_s;

    /** The compliance in the stress basis at a quadrature point: K(c, c')
     * = T_c : C(sigma) T_c', C the material's d^2 phi^c / d sigma^2 at the
     * stress state of the point (zero before a solve). */
    dealii::FullMatrix<double>                   K;
    std::vector<dealii::SymmetricTensor<2, dim>> T;
    dealii::SymmetricTensor<2, dim>              sigma_q;
    /** The component of each shape function and, per stress shape
     * function, the index pair of its basis tensor. */
    std::vector<unsigned int>                          comp_u, comp_s;
    std::vector<std::pair<unsigned int, unsigned int>> pq_s;
    std::vector<double>                                psi;

    CellBlocks blocks;
    /** In the value element: the blocks themselves, or scratch to reduce. */
    dealii::FullMatrix<double>  F_values, B_values, T_c;
    dealii::Vector<double>      strain_values, s_loc, beta;
    dealii::FullMatrix<double> *Fc, *Bc;
    dealii::Vector<double>     *st = nullptr;
    dealii::Vector<double>      force, pressure;
    /** Only after a first cell, and only where F_c does not depend on the
     * position or the stresses. */
    bool       reuse_blocks = false;
    const bool may_reuse;
    /** Each body its own law (Bodies): the cell's material id is its
     * body. */
    dealii::types::material_id previous_body;
    /** A stress constraint's term at its points (StressConstraintField). */
    std::unique_ptr<dealii::FEValues<dim>>       fv_vertex;
    dealii::FullMatrix<double>                   K_vertex;
    dealii::SymmetricTensor<2, dim>              P;
    std::vector<dealii::SymmetricTensor<2, dim>> DP;
  };
} // namespace hrcontact

#endif
