#include <deal.II/base/mpi.templates.h>

#include <hrcontact/adaptivity/cycle_state_transfer.h>
#include <hrcontact/postprocess/contact_fields.h>

#include <cmath>
#include <map>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  std::vector<double>
  contact_row_tributaries(const Results<dim> &results)
  {
    const EquilibriumSystem       &system = results.system;
    const unsigned int             nq     = system.contact_rows.size();
    std::map<unsigned int, double> node_measure;
    for (unsigned int k = 0; k < nq; ++k)
      node_measure[system.rows[system.contact_rows[k]].node] = 0;
    add_contact_tributaries(results.spaces.dof_handler_displacement,
                            true,
                            node_measure);
    std::vector<double> tributary(nq);
    for (unsigned int k = 0; k < nq; ++k)
      tributary[k] = node_measure[system.rows[system.contact_rows[k]].node];
    std::vector<double> total(nq);
    Utilities::MPI::sum(ArrayView<const double>(tributary),
                        results.partition.communicator,
                        ArrayView<double>(total));
    return total;
  }

  template <int dim>
  ContactStart
  carry_contact_state(const Results<dim> &previous, const Results<dim> &next)
  {
    AssertThrow(previous.contact,
                ExcMessage("the previous cycle has no contact state"));
    const std::vector<double> from = contact_row_tributaries(previous),
                              to   = contact_row_tributaries(next);
    // A row without contact faces around it (a point constraint): its
    // reaction is a force, carried as it is.
    auto ratio = [&](const unsigned int i, const unsigned int j) {
      return (from[j] > 0 && to[i] > 0) ? to[i] / from[j] : 1.;
    };
    ContactStart start = transfer_rows_by_position(
      previous.system,
      *previous.contact,
      next.system,
      ratio,
      [&](const unsigned int i, const unsigned int j) {
        return std::pow(ratio(i, j), (2. - dim) / (dim - 1.));
      },
      1.);
    double largest_before = 0, largest_now = 0;
    for (const double p : previous.contact->p)
      largest_before = std::max(largest_before, std::abs(p));
    for (const double p : start.p)
      largest_now = std::max(largest_now, std::abs(p));
    start.tolerance_scale =
      previous.contact->tolerance_scale *
      (largest_before > 0 ? largest_now / largest_before : 1.);
    start.origin = "the previous adaptive cycle's state";
    return start;
  }

  template std::vector<double>
  contact_row_tributaries<2>(const Results<2> &);
  template std::vector<double>
  contact_row_tributaries<3>(const Results<3> &);
  template ContactStart
  carry_contact_state<2>(const Results<2> &, const Results<2> &);
  template ContactStart
  carry_contact_state<3>(const Results<3> &, const Results<3> &);
} // namespace hrcontact
