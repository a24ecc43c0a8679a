#include <deal.II/base/exceptions.h>

#include <hrcontact/solvers/condensed/strain_loads.h>

#include <algorithm>

namespace hrcontact
{
  using namespace dealii;

  void
  StrainLoads::clear()
  {
    dofs.clear();
    values.clear();
  }

  void
  StrainLoads::add(const std::vector<types::global_dof_index> &du,
                   const Vector<double>                       &load)
  {
    cell_size = du.size(); // the same for all
    dofs.insert(dofs.end(), du.begin(), du.end());
    values.insert(values.end(), load.begin(), load.end());
  }

  void
  StrainLoads::for_each(
    const std::function<void(const std::vector<types::global_dof_index> &,
                             const Vector<double> &)> &f) const
  {
    if (dofs.empty())
      return;
    const std::size_t n = cell_size;
    AssertThrow(n > 0 && dofs.size() % n == 0, ExcInternalError());
    std::vector<types::global_dof_index> cell_dofs(n);
    Vector<double>                       cell_values(n);
    for (std::size_t first = 0; first < dofs.size(); first += n)
      {
        std::copy(dofs.begin() + first,
                  dofs.begin() + first + n,
                  cell_dofs.begin());
        std::copy(values.begin() + first,
                  values.begin() + first + n,
                  cell_values.begin());
        f(cell_dofs, cell_values);
      }
  }
} // namespace hrcontact
