#ifndef hrcontact_hr_assembler_h
#define hrcontact_hr_assembler_h

#include <hrcontact/equilibrium_system.h>
#include <hrcontact/mixed_spaces.h>
#include <hrcontact/scene.h>

namespace hrcontact
{
  /**
   * Assembles the Hellinger-Reissner blocks (section 4.2): the flexibility F,
   * the equilibrium matrix B, the loads f from body force and tractions, and
   * classifies the displacement rows into C (free), Q (normal constraint,
   * after a node-wise rotation to normal/tangents) and H (prescribed).
   */
  template <int dim>
  class HRAssembler
  {
  public:
    HRAssembler(const Scene<dim> &scene, const MixedSpaces<dim> &spaces);

    void
    assemble(EquilibriumSystem &system) const;

  private:
    void
    assemble_blocks(EquilibriumSystem &system) const;
    void
    classify_rows(EquilibriumSystem &system) const;

    const Scene<dim>       &scene;
    const MixedSpaces<dim> &spaces;
  };
  /**
   * The free directions of a node: Gram-Schmidt remainders of the unit axes
   * (in axis order) against the orthonormal directions `taken`, until they
   * span the space.
   */
  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  orthogonal_complement(const std::vector<dealii::Tensor<1, dim>> &taken);
} // namespace hrcontact

#endif
