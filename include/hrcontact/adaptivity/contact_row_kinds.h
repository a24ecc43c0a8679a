#ifndef hrcontact_contact_row_kinds_h
#define hrcontact_contact_row_kinds_h

#include <hrcontact/discretisation/equilibrium_system.h>

#include <string>

namespace hrcontact
{
  /**
   * The kinds of Q rows the error bound meets, read from the rows alone
   * (before the solve; ContactTractions and FaceTractions act on them):
   * obstacle rows, contact pair rows (unilateral or tied) whose slave node
   * coincides with a master node, and bilateral normal rows along an axis
   * that hold one displacement component.
   */
  class ContactRowKinds
  {
  public:
    /** Why the contact rows of @p system are not covered, or empty when
     * they are. */
    static std::string
    not_covered(const EquilibriumSystem &system);

    /** A bilateral normal row (Supports/Normal displacements) whose
     * direction is an axis: the dof it holds, which the vertex problems
     * treat as a prescribed component; else -1. */
    static long long
    held_dof(const EquilibriumSystem &system, const EquilibriumRow &row);

    /** A row over two bodies (a contact pair's). */
    static bool
    is_pair_row(const EquilibriumSystem &system, const EquilibriumRow &row);

    /** A contact pair's row whose master side is one node at the slave's
     * (its direction there -n, every other master node's zero): that node;
     * else numbers::invalid_unsigned_int (non-matching meshes, where the
     * relative displacement has a kink inside a face). 2D. */
    static unsigned int
    matched_master(const EquilibriumSystem &system, const EquilibriumRow &row);
  };
} // namespace hrcontact

#endif
