#ifndef hrcontact_gauss_point_cone_h
#define hrcontact_gauss_point_cone_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/material/stress_constraint.h>

#include <vector>

namespace hrcontact
{
  template <int dim>
  class StressConstraintField;

  /**
   * A stress constraint (no tension, no compression) imposed exactly at
   * every point where the compliance is integrated: the 2^dim Gauss points
   * of each cell (Stress constraint iteration/Method = closed-form
   * projection, doc/materials.md).
   *
   * Why it is sound and cheap: with the DGQ1 stresses and the compliance
   * integrated by those points, the stress field is fixed by its values at
   * the points and F_c is block diagonal per point (eq. 35), so the
   * complementary energy (eq. 22) maximised over the stresses in K splits
   * into one small problem per point, the projection of C eps onto K in the
   * compliance metric (StressConstraint::elastic_projection). What is left
   * is the primal problem of a no-tension body, minimise sum_q w_q W(eps_q)
   * - f . u, W convex and C^1: Newton's method on it (MaterialIteration)
   * takes one displacement solve per step with the consistent tangent D_q.
   *
   * It enters the existing Newton-step paths as a linearised law: at the
   * strain state eps_k of a point (sigma_k its projected stress), the
   * compliance F_q = (D_q + eta C)^{-1} and the strain term e_q = eps_k -
   * F_q sigma_k, so that the cell's stationarity F_q s_q + e_q = eps(u)_q
   * gives s_q = sigma_k + (D_q + eta C) (eps(u)_q - eps_k), the Newton
   * model. eta (Residual stiffness) keeps each system solvable where cracks
   * open in every direction (D_q = 0); it enters the tangent only, so the
   * converged stresses do not depend on it.
   *
   * With barrier > 0 (Method = interior point, BarrierPath) the point law
   * is the cone's log barrier instead (StressConstraint::
   * barrier_projection), smooth; the rest is unchanged.
   *
   * The state is a strain field in the stress unknowns' DGQ1 space (its
   * values at the Gauss points are the point strains), so that it lives,
   * is ghosted and is carried to a finer mesh like the stresses.
   */
  template <int dim>
  class GaussPointCone
  {
  public:
    GaussPointCone(const StressConstraint<dim> &constraint,
                   const Scene<dim>            &scene,
                   const MixedSpaces<dim>      &spaces,
                   const double                 residual_stiffness);

    /**
     * Evaluates the point law (stress and tangent) at every point of the
     * strain state @p state, which the Newton step's system is built at.
     * The other members read these values instead of evaluating the law
     * again: it is the costliest part of a step (an eigen-decomposition and
     * a scalar Newton iteration per point for the barrier), and it was
     * evaluated four times at this state per step (the system, the strains
     * of the solve, the line search's slope and curvature at its start).
     */
    void
    linearise(const FieldVector &state);

    /** The Newton model at point @p t of the cell with active index
     * @p cell, whose strain @p eps is that of the last linearise(): F_q
     * and e_q above. */
    void
    model(const unsigned int                     cell,
          const unsigned int                     t,
          const dealii::SymmetricTensor<2, dim> &eps,
          dealii::SymmetricTensor<4, dim>       &F,
          dealii::SymmetricTensor<2, dim>       &e) const;

    /**
     * The point strains of the last solve, eps(u)_q = F_q s_q + e_q with
     * the model built at @p state (the last linearise()), into @p strain
     * (sized like @p state, owned and ghost cells).
     */
    void
    strains_of_solve(const FieldVector &state,
                     const FieldVector &stress,
                     FieldVector       &strain) const;

    /**
     * The same from the displacements of the solve: the strains eps(u)_q
     * at the points, and the Newton model's stresses there, s_q = sigma_k
     * + D_q (eps(u)_q - eps_k) with sigma_k, D_q and eps_k of the last
     * linearise() (@p state). The condensed path's recovery s_c = F_c^{-1}
     * (B_c^T u - d_c) gives these stresses too (F_c block diagonal per
     * point, B_c and F_c integrated by the same points), through every
     * cell's blocks instead of one gradient per point (the manufactured
     * pier at 790k dofs: 0.4 s a step, a fifth of a floor).
     */
    void
    strains_and_stresses(const FieldVector &u,
                         const FieldVector &state,
                         FieldVector       &strain,
                         FieldVector       &stress) const;

    /**
     * How far the last solve is from a solution: max_q |sigma(eps_q) - s_q|
     * and max_q |s_q| (over every process), with @p strain from
     * strains_of_solve. s is
     * equilibrated (the path solved for it), sigma(eps) lies in the cone
     * and is the law's stress of compatible strains: where they agree, the
     * answer is exact. 0 at a solution whatever the displacements do in
     * cracked regions (there they are not unique, and the strains may keep
     * moving while the stresses are converged).
     */
    std::pair<double, double>
    model_error(const FieldVector &stress, const FieldVector &strain) const;

    /**
     * Along eps0 + theta delta: sum_q w_q sigma(eps_theta) : delta_q over
     * the owned cells of every process, and with @p curvature the model's
     * second derivative sum_q w_q delta_q : (D_q + eta C) delta_q at eps0
     * (MaterialIteration's exact line search). @p eps0 is the state of the
     * last linearise(): at theta = 0 and for the curvature its values are
     * read, not evaluated again.
     */
    double
    slope(const FieldVector &eps0,
          const FieldVector &delta,
          const double       theta,
          double            *curvature) const;

    /** The fracture strains of the strain state at the points of
     * @p field (a Gauss-point StressConstraintField), for output. */
    void
    store_fracture_strains(const FieldVector          &strain,
                           StressConstraintField<dim> &field) const;

    /** The largest |eps| at any point of every process. */
    double
    largest_strain(const FieldVector &strain) const;

    const StressConstraint<dim> &constraint;
    double                       residual_stiffness;
    /** tau of the log barrier (Method = interior point, BarrierPath); 0:
     * the closed-form projection. */
    double barrier = 0;
    /** The principal stress of the wrong sign the barrier allows. */
    double allowance = 0;

  private:
    /** In-plane Lame constants of the body's elastic law. */
    std::pair<double, double>
    lame(const dealii::types::material_id body) const;

    /** The point's stress and (if asked) the tangent with the residual
     * stiffness. */
    void
    point_stress(const dealii::SymmetricTensor<2, dim> &eps,
                 const dealii::types::material_id       body,
                 dealii::SymmetricTensor<2, dim>       &sigma,
                 dealii::SymmetricTensor<4, dim>       *tangent) const;

    /** Visits the points of every cell this process holds: (cell, owned,
     * body, t, JxW, value of each vector at t). */
    template <typename Visitor>
    void
    for_each_point(const std::vector<const FieldVector *> &vectors,
                   const Visitor                          &visit) const;

    /** Dof values of the cell from its point values (per component: the
     * inverse of the DGQ1 shape values at the Gauss points). */
    void
    set_point_values(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      const std::vector<dealii::SymmetricTensor<2, dim>>           &values,
      FieldVector                                                  &v) const;

    /** The law at a point of the last linearise(): its stress and its
     * tangent with the residual stiffness. */
    struct PointModel
    {
      dealii::SymmetricTensor<2, dim> sigma;
      dealii::SymmetricTensor<4, dim> tangent;
    };
    /** Per active cell index, n_points after another (artificial cells
     * unused). */
    std::vector<PointModel> linearised;
    /** 2^dim. */
    static constexpr unsigned int n_points = 1u << dim;
    const PointModel &
    linearised_at(const unsigned int cell, const unsigned int t) const;

    const Scene<dim>                            &scene;
    const MixedSpaces<dim>                      &spaces;
    dealii::FullMatrix<double>                   point_to_dof;
    std::vector<dealii::SymmetricTensor<2, dim>> T;
  };
} // namespace hrcontact

#endif
