#ifndef hrcontact_field_recovery_h
#define hrcontact_field_recovery_h

#include <hrcontact/core/results.h>
#include <hrcontact/solvers/newton_step_path.h>

namespace hrcontact
{
  /**
   * The fields of a run from its path's last solve: the stresses (expanded
   * from a parametric element's unknowns), the displacements of eq. 51, the
   * contact and support reactions and each contact node's displacement.
   */
  template <int dim>
  void
  recover_fields(const NewtonStepPath &path, Results<dim> &results);
} // namespace hrcontact

#endif
