#ifndef hrcontact_cycle_state_transfer_h
#define hrcontact_cycle_state_transfer_h

#include <hrcontact/core/results.h>
#include <hrcontact/solvers/nested_iteration.h>

#include <vector>

namespace hrcontact
{
  /**
   * Each Q row's tributary measure: the share of its node in the contact
   * faces around it (a face's measure over its vertices, summed over the
   * faces whose vertices all carry rows), summed over the processes' owned
   * cells, so every process has every row's. Several rows of one node
   * share the node's measure.
   */
  template <int dim>
  std::vector<double>
  contact_row_tributaries(const Results<dim> &results);

  /**
   * The converged contact state of the previous adaptive cycle, carried to
   * the rows of the next cycle's mesh (transfer_rows_by_position). The two
   * meshes differ locally, refined in some places and coarsened in others,
   * so the scales are per row: a reaction is a pressure times its node's
   * tributary measure, and carries the pressure (reaction_j / tributary_j
   * times tributary_i); a compliance scales with the nodal compliance
   * h^{2-dim} (2D: unchanged; 3D: the square root of the tributaries'
   * ratio, inverted). The multipliers (gaps) carry unchanged. The force
   * scale of the tolerance is the previous cycle's, times the ratio of the
   * largest carried reaction to the largest previous one: the reactions
   * shrink where the mesh was refined, as between nested levels.
   */
  template <int dim>
  ContactStart
  carry_contact_state(const Results<dim> &previous, const Results<dim> &next);
} // namespace hrcontact

#endif
