#include <hrcontact/core/input.h>
#include <hrcontact/discretisation/reactions.h>
#include <hrcontact/solvers/field_recovery.h>

namespace hrcontact
{
  template <int dim>
  void
  recover_fields(const NewtonStepPath &path, Results<dim> &r)
  {
    // The solver's stress unknowns; Results::stress holds their values
    // (the same vector unless the stress element has parameters).
    FieldVector unknowns;
    reinit_field(unknowns, r.spaces.stress_unknowns());
    path.stresses(unknowns);
    reinit_field(r.stress, r.spaces.dof_handler_stress);
    r.spaces.expand(unknowns, r.stress);
    reinit_field(r.displacement, r.spaces.dof_handler_displacement);
    path.displacements(r.reactions.contact_w, r.displacement);
    // The Q rows first: a pair row's reaction enters its master rows'.
    row_reactions(r.system,
                  r.partition,
                  unknowns,
                  r.system.contact_rows,
                  r.reactions.contact,
                  r.reactions.contact);
    row_reactions(r.system,
                  r.partition,
                  unknowns,
                  r.system.prescribed_rows,
                  r.reactions.contact,
                  r.reactions.support);
    if (r.spaces.has_parameters())
      r.stress_parameters.swap(unknowns);
    else
      r.stress_parameters.reinit(0);
    r.reactions.contact_node_displacement =
      contact_node_displacements(r.system, r.partition, r.displacement);
  }

  template void
  recover_fields<2>(const NewtonStepPath &, Results<2> &);
  template void
  recover_fields<3>(const NewtonStepPath &, Results<3> &);
} // namespace hrcontact
