#ifndef hrcontact_sorted_rows_h
#define hrcontact_sorted_rows_h

#include <hrcontact/discretisation/equilibrium_system.h>

#include <functional>
#include <vector>

namespace hrcontact
{
  /** Indices k of the selected Q rows (system.contact_rows[k]), sorted by
   * their node's x, then y, then z: the order of the tables. */
  std::vector<unsigned int>
  sorted_q_rows(const EquilibriumSystem                           &system,
                const std::function<bool(const EquilibriumRow &)> &select);

  /** The unilateral Q rows, sorted. */
  std::vector<unsigned int>
  sorted_contact_rows(const EquilibriumSystem &system);

  /** The two-sided stop rows among the Q rows, sorted. */
  std::vector<unsigned int>
  sorted_stop_rows(const EquilibriumSystem &system);
} // namespace hrcontact

#endif
