#include <hrcontact/postprocess/contact_fields.h>

#include <algorithm>
#include <limits>
#include <map>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** What a node's contact rows say, before the division by its
     * tributary measure. */
    struct NodeContact
    {
      double reaction  = 0;
      double gap       = std::numeric_limits<double>::max();
      double status    = 0;
      double tributary = 0;
    };

    /** Status code of one row (see ContactFields). */
    double
    row_status(const EquilibriumRow &row, const bool released)
    {
      if (released)
        return 1;
      return row.law ? 3 : 2;
    }
  } // namespace

  template <int dim>
  void
  add_contact_tributaries(const DoFHandler<dim>          &displacement_dofs,
                          const bool                      owned_only,
                          std::map<unsigned int, double> &tributary)
  {
    for (const auto &cell : displacement_dofs.active_cell_iterators())
      if (owned_only ? cell->is_locally_owned() : !cell->is_artificial())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto face = cell->face(f);
              bool       all  = true;
              for (const auto v : face->vertex_indices())
                all &= tributary.count(face->vertex_dof_index(v, 0) / dim) > 0;
              if (!all)
                continue;
              const double share = face->measure() / face->n_vertices();
              for (const auto v : face->vertex_indices())
                tributary[face->vertex_dof_index(v, 0) / dim] += share;
            }
  }

  template <int dim>
  ContactFields<dim>::ContactFields(const Results<dim> &results)
    : fe(1)
    , dof_handler(results.triangulation())
  {
    const EquilibriumSystem            &system  = results.system;
    const ContactIteration             &contact = *results.contact;
    const unsigned int                  n_rows  = system.contact_rows.size();
    std::map<unsigned int, NodeContact> nodes;
    for (unsigned int k = 0; k < n_rows; ++k)
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[k]];
        if (!row.unilateral && !row.law)
          continue;
        NodeContact &node = nodes[row.node];
        node.reaction += results.reactions.contact[k];
        node.gap =
          std::min(node.gap, row.value - results.reactions.contact_w[k]);
        node.status =
          std::max(node.status, row_status(row, contact.released[k]));
      }

    // Tributary measures from the contact faces of this process's own and
    // ghost cells: complete for every node of its own cells.
    const auto &u_dofs = results.spaces.dof_handler_displacement;
    std::map<unsigned int, double> tributary;
    for (const auto &[node, c] : nodes)
      tributary[node] = 0;
    add_contact_tributaries(u_dofs, false, tributary);
    for (auto &[node, c] : nodes)
      c.tributary = tributary[node];

    dof_handler.distribute_dofs(fe);
    reinit_field(pressure, dof_handler);
    reinit_field(gap, dof_handler);
    reinit_field(status, dof_handler);
    auto u_cell = u_dofs.begin_active();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_artificial())
          for (const auto v : cell->vertex_indices())
            {
              const types::global_dof_index i = cell->vertex_dof_index(v, 0);
              const auto                    node =
                nodes.find(u_cell->vertex_dof_index(v, 0) / dim);
              if (node == nodes.end() || !pressure.in_local_range(i))
                continue;
              const NodeContact &c = node->second;
              pressure(i) = c.tributary > 0 ? -c.reaction / c.tributary : 0.;
              gap(i)      = c.gap;
              status(i)   = c.status;
            }
        ++u_cell;
      }
    for (FieldVector *v : {&pressure, &gap, &status})
      v->update_ghost_values();
  }

  template <int dim>
  void
  ContactFields<dim>::add_to(DataOut<dim> &data_out) const
  {
    data_out.add_data_vector(dof_handler, pressure, "contact_pressure");
    data_out.add_data_vector(dof_handler, gap, "contact_gap");
    data_out.add_data_vector(dof_handler, status, "contact_status");
  }

  template void
  add_contact_tributaries<2>(const DoFHandler<2> &,
                             const bool,
                             std::map<unsigned int, double> &);
  template void
  add_contact_tributaries<3>(const DoFHandler<3> &,
                             const bool,
                             std::map<unsigned int, double> &);
  template class ContactFields<2>;
  template class ContactFields<3>;
} // namespace hrcontact
