#ifndef hrcontact_stress_constraint_field_h
#define hrcontact_stress_constraint_field_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/material/stress_constraint.h>

#include <vector>

namespace hrcontact
{
  /**
   * The augmented Lagrangian state of a stress constraint (StressConstraint):
   * a multiplier mu (the fracture strain of a no-tension body) at each
   * constraint point of each cell this process assembles, and the penalty
   * alpha (a compliance, eq. 49 grows it). The points, each weighted by its
   * rule's JxW: the vertices (default; for DGQ1 the stress dofs, so that
   * the whole bilinear field is admissible), the 2^dim Gauss points, or
   * the cell centre. The first two can over-constrain the four-node stress
   * field: near free edges and crack fronts no finite multipliers may
   * exist, and the residual then only falls like alpha^-1/2; the centre
   * leaves the bilinear modes free (doc/materials.md).
   */
  template <int dim>
  class StressConstraintField
  {
  public:
    /** Where the cone is imposed (Stress constraint iteration/Constraint
     * points). */
    enum class Points
    {
      cell_centres,
      gauss_points,
      vertices
    };

    StressConstraintField(const StressConstraint<dim> &constraint,
                          const MixedSpaces<dim>      &spaces,
                          const Points                 points);

    /** The vertex rule the constraint is imposed with. */
    const dealii::Quadrature<dim> &
    quadrature() const
    {
      return rule;
    }

    /** mu at point t of the cell with this active cell index. */
    const dealii::SymmetricTensor<2, dim> &
    multiplier(const unsigned int cell, const unsigned int t) const
    {
      return mu[cell * rule.size() + t];
    }

    /** Sets mu at point t of a cell (GaussPointCone: its fracture
     * strains, for output). */
    void
    set_multiplier(const unsigned int                     cell,
                   const unsigned int                     t,
                   const dealii::SymmetricTensor<2, dim> &m)
    {
      mu[cell * rule.size() + t] = m;
    }

    /**
     * The multiplier update (eq. 48): mu <- P(mu + alpha sigma) at every
     * point of the owned and ghost cells, sigma from `stress` (its ghost
     * entries up to date). Returns max |mu_new - mu_old| / alpha over the
     * owned points of every process, in stress units: the constraint's
     * residual, 0 exactly at a solution.
     */
    double
    update_multipliers(const FieldVector &stress);

    /** The largest violation (StressConstraint::violation) over every
     * process's owned points. */
    double
    largest_violation(const FieldVector &stress) const;

    /**
     * The fraction of the area (volume) whose points have a multiplier
     * larger than `threshold` times the largest (opened, cracked), each
     * point weighted by its vertex-rule weight; over every process.
     */
    double
    cracked_fraction(const double threshold = 1e-2) const;

    /**
     * The largest opening of the points of the cell around `point` (found
     * by the process that owns it; 0 outside the mesh), over every process.
     */
    double
    opening_at(const dealii::Point<dim> &point) const;

    /** The largest StressConstraint::opening of a multiplier. */
    double
    largest_opening() const;

    /**
     * Per active cell, the largest opening of its points (0 on cells of
     * other processes): the cracked field for output.
     */
    dealii::Vector<float>
    cell_openings() const;

    const StressConstraint<dim> &constraint;
    /** The penalty: a compliance (strain per stress). */
    double alpha = 1;

  private:
    const MixedSpaces<dim>                      &spaces;
    const dealii::Quadrature<dim>                rule;
    std::vector<dealii::SymmetricTensor<2, dim>> mu;
    /** Vertex-rule weights JxW per point, for the cracked fraction. */
    std::vector<double> weights;
  };
} // namespace hrcontact

#endif
