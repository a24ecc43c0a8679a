#ifndef hrcontact_hr_assembler_h
#define hrcontact_hr_assembler_h

#include <deal.II/lac/vector.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <memory>

namespace hrcontact
{
  template <int dim>
  class StressConstraintField;
  template <int dim>
  class GaussPointCone;

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

    /**
     * The C, Q and H rows, the nodes and the dimensions of the system
     * (RowClassification);
     * with `lean_rows`, the free rows of unconstrained nodes stay implicit
     * (EquilibriumSystem::lean_rows).
     */
    void
    classify_rows(EquilibriumSystem &system,
                  const bool         lean_rows = false) const;

    /**
     * B, F and the load f; needs the rows. Without `lean`, every cell's
     * blocks are stored. With it (the condensed path), only the cells
     * touching a Q or H row's node are (EquilibriumSystem::stored_cell), the
     * assembler is left behind as EquilibriumSystem::recompute_cell_blocks,
     * and each process evaluates only its own cells and the stored ones; the
     * load is summed over the processes. The scene and the spaces must
     * outlive the system then.
     */
    void
    assemble_blocks(EquilibriumSystem  &system,
                    const DofPartition *lean = nullptr) const;

    /**
     * Computes the blocks of every cell the filter accepts, in cell order,
     * and hands them to the worker. Throws InputError for an inverted cell
     * or a load that is not finite.
     */
    void
    for_each_cell(const std::function<bool(unsigned int)>       &filter,
                  const std::function<void(const CellBlocks &)> &worker) const;

    /**
     * A material whose compliance depends on its state (MaterialLaw): F_c
     * again for the stored cells with the material evaluated at the
     * stresses s at each quadrature point; a lean system recomputes every
     * other cell with the same state. A nonlinear law also gets the strain
     * terms d_c of its Newton step about s (EquilibriumSystem::
     * cell_strain_term), for the stored cells. Call NewtonStepPath::
     * flexibility_changed() afterwards. On a distributed mesh `stress`
     * holds the owned and ghost cells' stresses (NewtonStepPath::stresses
     * fills them), which are all the cells a process assembles.
     */
    void
    refresh_flexibility(EquilibriumSystem &system, const FieldVector &stress);
    /** The same from a vector of every stress dof (a serial mesh). */
    void
    refresh_flexibility(EquilibriumSystem            &system,
                        const dealii::Vector<double> &stress);

    /**
     * Along the line s(theta) = s0 + theta delta of stress vectors, the
     * derivative of the cell energies, sum_c int eps(sigma_theta) : delta
     * sigma (the law's complementary energy at the Gauss points) plus the
     * stress constraint's term at its points, sum_t w_t P(mu + alpha
     * sigma_theta) : delta sigma_t; and, when `curvature` is given, delta^T
     * F(s0) delta, the same energies' second derivative at s0 (F_c as
     * refresh_flexibility assembles it). Sums over the owned cells of every
     * process. MaterialIteration's line search uses them.
     */
    double
    energy_slope(const FieldVector &s0,
                 const FieldVector &delta,
                 const double       theta,
                 double            *curvature = nullptr) const;

    /**
     * The augmented Lagrangian state of the scene's stress constraint
     * (Material/Admissible stresses), if any: refresh_flexibility then adds
     * its term at the constraint points to F_c and d_c. Owned by the caller.
     */
    const StressConstraintField<dim> *constraint_field = nullptr;

    /**
     * A stress constraint imposed in closed form at the Gauss points
     * (GaussPointCone): refresh_flexibility then reads its argument as the
     * strain state and assembles the cone's Newton model. Owned by the
     * caller.
     */
    const GaussPointCone<dim> *cone = nullptr;

  private:
    const Scene<dim>       &scene;
    const MixedSpaces<dim> &spaces;
    /** Leave this assembler (with its stress state) behind as the
     * system's recompute_cell_blocks. */
    void
    set_recompute(EquilibriumSystem &system) const;
    /** The stresses the material is evaluated at (null: zero stress). */
    std::shared_ptr<const FieldVector> stress_state;
  };
} // namespace hrcontact

#endif
