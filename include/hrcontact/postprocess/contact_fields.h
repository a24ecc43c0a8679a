#ifndef hrcontact_contact_fields_h
#define hrcontact_contact_fields_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/numerics/data_out.h>

#include <hrcontact/core/results.h>
#include <hrcontact/discretisation/field_vector.h>

#include <map>

namespace hrcontact
{
  /**
   * Add to each node of @p tributary (keyed by node: displacement dof / dim)
   * its share of the boundary faces whose nodes are all keys: the face's
   * measure over its vertices. Over this process's own cells only
   * (`owned_only`: sum over the processes afterwards) or its own and ghost
   * cells (complete for every node of its own cells, no communication).
   */
  template <int dim>
  void
  add_contact_tributaries(const dealii::DoFHandler<dim>  &displacement_dofs,
                          const bool                      owned_only,
                          std::map<unsigned int, double> &tributary);

  /**
   * The contact rows (unilateral contact and constraint laws such as stops)
   * as nodal fields for ParaView, on a scalar Q1 space of the mesh:
   * - contact_pressure: minus the sum of the node's reactions p (p <= 0 in
   *   contact) over its tributary length (2D) or area (3D) of the contact
   *   faces, positive in compression, the nodal pressure of contact.csv's
   *   p_n;
   * - contact_gap: g - w_n, the open distance left to the obstacle or the
   *   other body (0 where pressed), the smallest of the node's rows;
   * - contact_status: 0 no contact row, 1 released (open), 2 pressed, 3 on a
   *   stop's limit (a constraint law's branch that transmits a reaction).
   * A contact face is a boundary face whose every node has a contact row.
   * The fields are zero at the other nodes, so that inside the cells next to
   * the contact surface ParaView interpolates towards zero: read them on the
   * surface (threshold contact_status >= 1).
   */
  template <int dim>
  class ContactFields
  {
  public:
    /** Compute the fields; needs results.contact. */
    explicit ContactFields(const Results<dim> &results);

    /** Add the three fields to data_out (this object must outlive it). */
    void
    add_to(dealii::DataOut<dim> &data_out) const;

    /** The scalar Q1 space of the fields. */
    const dealii::DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    /** The fields: this process's own and ghost entries on a distributed
     * mesh, complete on a serial one. */
    const FieldVector &
    get_pressure() const
    {
      return pressure;
    }
    const FieldVector &
    get_gap() const
    {
      return gap;
    }
    const FieldVector &
    get_status() const
    {
      return status;
    }

  private:
    dealii::FE_Q<dim>       fe;
    dealii::DoFHandler<dim> dof_handler;
    FieldVector             pressure, gap, status;
  };
} // namespace hrcontact

#endif
