#ifndef hrcontact_pian_sumihara_h
#define hrcontact_pian_sumihara_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <hrcontact/discretisation/stress_element.h>

#include <array>
#include <vector>

namespace hrcontact
{
  /**
   * The assumed-stress fields of Pian and Sumihara (2D, five parameters:
   * T.H.H. Pian, K. Sumihara, Rational approach for assumed stress finite
   * elements, Int. J. Numer. Meth. Engng 20 (1984) 1685-1695) and of Pian
   * and Tong (3D, eighteen: T.H.H. Pian, P. Tong, Relations between
   * incompatible displacement model and hybrid stress model, Int. J.
   * Numer. Meth. Engng 22 (1986) 173-181), Finite elements/Stress element =
   * Pian-Sumihara in either dimension.
   *
   * With t_i the cell's tangents dx/dxi_i at its centre (the columns of
   * J_0, here normalised to unit length so that every parameter is a
   * stress), the field is a constant stress plus linear terms in the
   * natural coordinates xi, eta, zeta in [-1, 1]:
   *
   *   2D: sigma = sigma_0 + b_4 eta t_1 t_1 + b_5 xi t_2 t_2,
   *   3D: S_11 gets eta, zeta, eta zeta; S_22 zeta, xi, zeta xi;
   *       S_33 xi, eta, xi eta; S_12 zeta; S_23 xi; S_13 eta,
   *
   * sigma = sum S_ij sym(t_i t_j). The constant part passes the patch
   * test; the linear terms are the fewest that give the element the rank
   * of its displacement modes (2n - 3 = 5, 3n - 6 = 18), and they are
   * exactly the bending stresses of the cell's own directions: no parasitic
   * shear (shear locking) and no volumetric stress mode that would lock as
   * nu -> 1/2, unlike DGQ1, whose twelve (48) parameters reproduce the Q1
   * displacement element. Each term is affine (3D: multi-affine) in the
   * natural coordinates, hence exactly a DGQ1 field: the value element is
   * DGQ1.
   */
  template <int dim>
  class PianSumihara : public StressElement<dim>
  {
  public:
    static constexpr unsigned int n_parameters = (dim == 2 ? 5 : 18);

    std::unique_ptr<dealii::FESystem<dim>>
    value_element() const override;

    std::unique_ptr<dealii::FESystem<dim>>
    parameter_element() const override;

    void
    expansion(const typename dealii::Triangulation<dim>::cell_iterator &cell,
              const dealii::FiniteElement<dim> &value_fe,
              dealii::FullMatrix<double>       &T) const override;

    /**
     * The stress of each parameter at the natural coordinates xi (in [-1,
     * 1]^dim) for the tangents t: parameters 0..n_comp-1 are the Cartesian
     * constant stresses, the rest the linear terms above.
     */
    static std::array<dealii::SymmetricTensor<2, dim>, n_parameters>
    fields(const std::array<dealii::Tensor<1, dim>, dim> &t,
           const dealii::Point<dim>                      &xi);

    /** The unit tangents dx/dxi_i of a Q1 cell at its centre. */
    static std::array<dealii::Tensor<1, dim>, dim>
    centre_tangents(
      const typename dealii::Triangulation<dim>::cell_iterator &cell);
  };
} // namespace hrcontact

#endif
