#ifndef hrcontact_condensed_strain_loads_h
#define hrcontact_condensed_strain_loads_h

#include <deal.II/base/types.h>

#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace hrcontact
{
  /**
   * The loads a material Newton step adds beside K (EquilibriumSystem::
   * cell_strain_term): per owned cell B_c F_c^{-1} d_c with the cell's
   * displacement dofs, cell after cell (every cell has as many dofs). Empty
   * for a linear law.
   */
  class StrainLoads
  {
  public:
    void
    clear();

    /** The next cell's load. */
    void
    add(const std::vector<dealii::types::global_dof_index> &dofs,
        const dealii::Vector<double>                       &load);

    /** f(dofs, load) for each cell, in the order they were added. */
    void
    for_each(const std::function<
             void(const std::vector<dealii::types::global_dof_index> &,
                  const dealii::Vector<double> &)> &f) const;

  private:
    std::vector<dealii::types::global_dof_index> dofs;
    std::vector<double>                          values;
    std::size_t                                  cell_size = 0;
  };
} // namespace hrcontact

#endif
