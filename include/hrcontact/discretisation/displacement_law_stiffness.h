#ifndef hrcontact_displacement_law_stiffness_h
#define hrcontact_displacement_law_stiffness_h

#include <deal.II/base/symmetric_tensor.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/displacement_stiffness.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <vector>

namespace hrcontact
{
  /**
   * The scene's material law solved the way a displacement code must:
   * Newton's method on the Q1 displacements u, the law's stress at each
   * Gauss point found from the strain eps(u) by inverting the law there
   * (local Newton on strain(sigma) = eps, the compliance its Jacobian), and
   * the tangent D = C(sigma)^-1 in the stiffness. The comparison that
   * doc/materials.md asks of a law given by its complementary potential
   * (Output/Compare with a displacement code): the stress code evaluates
   * eps(sigma) directly, the displacement code inverts it at every point
   * and every step. This class is the cell stiffness and the load of one
   * step: K_c = int B^T D B and K_c u_c - int B^T sigma (CellStiffness), so
   * that CondensedStep solves K du = f - f_int(u) with the run's supports,
   * processes and linear solver.
   */
  template <int dim>
  class DisplacementLawStiffness : public CellStiffness
  {
  public:
    DisplacementLawStiffness(const Scene<dim>       &scene,
                             const MixedSpaces<dim> &spaces);

    /**
     * The stresses and tangents at the Gauss points of every cell this
     * process holds for the displacement u (its ghost entries up to date),
     * each point's local Newton iteration starting from its last stress.
     * Returns the largest number of local steps a point took (over every
     * process); throws NotConvergedError if one does not converge.
     */
    unsigned int
    linearise_at(const FieldVector &u);

    void
    for_each_cell(const std::function<bool(unsigned int)> &filter,
                  const Worker &worker) const override;

  private:
    const Scene<dim>       &scene;
    const MixedSpaces<dim> &spaces;
    /** Per cell and Gauss point: the stress and the tangent D. */
    std::vector<dealii::SymmetricTensor<2, dim>> stress;
    std::vector<dealii::SymmetricTensor<4, dim>> tangent;
    /** u at the last linearisation (for the load K_c u_c). */
    FieldVector displacement;
  };
} // namespace hrcontact

#endif
