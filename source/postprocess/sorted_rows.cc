#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/postprocess/sorted_rows.h>

#include <algorithm>

namespace hrcontact
{
  std::vector<unsigned int>
  sorted_q_rows(const EquilibriumSystem                           &system,
                const std::function<bool(const EquilibriumRow &)> &select)
  {
    std::vector<unsigned int> order;
    for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
      if (select(system.rows[system.contact_rows[k]]))
        order.push_back(k);
    auto coordinates = [&system](const unsigned int k) {
      return system.node_coordinates[system.rows[system.contact_rows[k]].node];
    };
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](unsigned int a, unsigned int b) {
                       return coordinates(a) < coordinates(b);
                     });
    return order;
  }

  std::vector<unsigned int>
  sorted_contact_rows(const EquilibriumSystem &system)
  {
    return sorted_q_rows(system, [](const EquilibriumRow &row) {
      return row.unilateral;
    });
  }

  std::vector<unsigned int>
  sorted_stop_rows(const EquilibriumSystem &system)
  {
    return sorted_q_rows(system, [](const EquilibriumRow &row) {
      return dynamic_cast<const TwoSidedStop *>(row.law.get()) != nullptr;
    });
  }
} // namespace hrcontact
