#ifndef hrcontact_displacement_stiffness_h
#define hrcontact_displacement_stiffness_h

#include <deal.II/base/types.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/mixed_spaces.h>

#include <functional>
#include <vector>

namespace hrcontact
{
  /**
   * Cell stiffness matrices of a displacement bilinear form, cell by cell:
   * what CondensedStep assembles instead of B_c F_c^-1 B_c^T when it is
   * given one. Dimension-free, as the paths are.
   */
  class CellStiffness
  {
  public:
    /**
     * (cell, its displacement dofs, K_c, a load of the cell added to the
     * right-hand side: empty for none; a Newton step's K_c u_c - f_int,c).
     */
    using Worker =
      std::function<void(const unsigned int cell,
                         const std::vector<dealii::types::global_dof_index> &,
                         const dealii::FullMatrix<double> &,
                         const dealii::Vector<double> &)>;
    virtual ~CellStiffness() = default;
    /** Calls the worker with the matrix of every cell the filter accepts. */
    virtual void
    for_each_cell(const std::function<bool(unsigned int)> &filter,
                  const Worker                            &worker) const = 0;
  };

  /**
   * The plain Q1 displacement stiffness of linear isotropic elasticity,
   * K_ij = int eps(phi_i) : C eps(phi_j), assembled the standard way
   * (deal.II's step-8): the floor that the benchmarks measure the contact
   * solve against (Output/Time the Q1 floor). Needs Material/Model = linear
   * elasticity. On parallelograms it equals B F^-1 B^T with DGQ1 stresses
   * (tests/hr_equals_q1, tests/floor_solve).
   */
  template <int dim>
  class DisplacementStiffness : public CellStiffness
  {
  public:
    DisplacementStiffness(const Scene<dim>       &scene,
                          const MixedSpaces<dim> &spaces);
    void
    for_each_cell(const std::function<bool(unsigned int)> &filter,
                  const Worker &worker) const override;

  private:
    const MixedSpaces<dim> &spaces;
    /** Lame constants of the (plane strain, plane stress or 3D) law, by
     * body (the cell's material id). */
    std::vector<double> lambda, mu;
  };
} // namespace hrcontact

#endif
