#include <deal.II/base/utilities.h>

#include <hrcontact/postprocess/contact_tables.h>
#include <hrcontact/postprocess/sorted_rows.h>

#include <array>
#include <iomanip>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  void
  ContactTables<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "Tracked contact nodes",
      "",
      Patterns::Anything(),
      "Points 'x, y [, z]' separated by '|': the nearest contact node of each "
      "gets its normal displacement and reaction at every multiplier update "
      "written to contact-history.csv (k, node, x, y, w_n, p_n, alpha, "
      "status).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ContactTables<dim>::parse_parameters(ParameterHandler &prm, const Constants &)
  {
    prm.enter_subsection("Postprocess");
    tracked_nodes = prm.get("Tracked contact nodes");
    prm.leave_subsection();
  }

  template <int dim>
  std::string
  ContactTables<dim>::skip_reason(const Results<dim> &results) const
  {
    return results.contact ? "" : "the scene has no contact";
  }

  namespace
  {
    /** stops.csv: one row per two-sided stop, sorted by x, y (, z). */
    template <int dim>
    void
    write_stops_table(const Results<dim> &results, PostprocessOutput &output)
    {
      const EquilibriumSystem        &system     = results.system;
      const ContactIteration         &contact    = *results.contact;
      const char                     *xyz        = "xyz";
      const std::vector<unsigned int> stop_order = sorted_stop_rows(system);
      if (!stop_order.empty())
        write_file_atomically(
          output.communicator,
          output.directory + "/stops.csv",
          [&](std::ostream &out) {
            for (unsigned int d = 0; d < dim; ++d)
              out << xyz[d] << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << "d" << xyz[d] << ",";
            out << "g_minus,g_plus,p0_minus,p0_plus,k_minus,k_plus,w,";
            for (unsigned int d = 0; d < dim; ++d)
              out << "reaction_" << xyz[d] << ",";
            out << "p,mu,alpha,branch\n";
            out << std::setprecision(12);
            for (const unsigned int k : stop_order)
              {
                const EquilibriumRow &row = system.rows[system.contact_rows[k]];
                const auto &stop = dynamic_cast<const TwoSidedStop &>(*row.law);
                double      w    = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    out << system.node_coordinates[row.node][d] << ",";
                    w += row.combination[d].second *
                         results.reactions.contact_node_displacement[k][d];
                  }
                for (unsigned int d = 0; d < dim; ++d)
                  out << row.combination[d].second << ",";
                out << stop.g_minus << "," << stop.g_plus << ","
                    << stop.p0_minus << "," << stop.p0_plus << ","
                    << stop.k_minus << "," << stop.k_plus << "," << w << ",";
                for (unsigned int d = 0; d < dim; ++d)
                  out << results.reactions.contact[k] *
                           row.combination[d].second
                      << ",";
                out << results.reactions.contact[k] << "," << contact.mu[k]
                    << "," << contact.alpha[k] << ","
                    << stop.branch_name(contact.pieces[k].branch) << "\n";
              }
          });
    }

    /** The contact row nearest to each point of Postprocess/Tracked contact
     * nodes ("x, y | x, y"), among @p order. */
    template <int dim>
    std::vector<unsigned int>
    nearest_contact_rows(const Results<dim>              &results,
                         const std::vector<unsigned int> &order,
                         const std::string               &tracked_nodes)
    {
      const EquilibriumSystem  &system = results.system;
      std::vector<unsigned int> tracked;
      for (const std::string &text : split_and_trim(tracked_nodes, '|'))
        {
          const auto coords = split_and_trim(text, ',');
          if (coords.size() != dim)
            throw InputError("Postprocess/Tracked contact nodes: '" + text +
                             "' is not a point with " + std::to_string(dim) +
                             " coordinates.");
          std::array<double, 3> x = {{0, 0, 0}};
          for (unsigned int d = 0; d < dim; ++d)
            x[d] =
              evaluate_constant_expression(coords[d],
                                           results.scene.constants,
                                           "Postprocess/Tracked contact nodes");
          double       best    = std::numeric_limits<double>::max();
          unsigned int nearest = order.front();
          for (const unsigned int k : order)
            {
              const auto &c =
                system
                  .node_coordinates[system.rows[system.contact_rows[k]].node];
              double dist = 0;
              for (unsigned int d = 0; d < dim; ++d)
                dist += (c[d] - x[d]) * (c[d] - x[d]);
              if (dist < best)
                {
                  best    = dist;
                  nearest = k;
                }
            }
          tracked.push_back(nearest);
        }
      return tracked;
    }
  } // namespace

  template <int dim>
  void
  ContactTables<dim>::execute(const Results<dim> &results,
                              PostprocessOutput  &output)
  {
    const EquilibriumSystem &system  = results.system;
    const ContactIteration  &contact = *results.contact;
    // contact.csv: one row per unilateral constraint, sorted by x, y (, z).
    const std::vector<unsigned int> order = sorted_contact_rows(system);
    const char                     *xyz   = "xyz";
    write_file_atomically(
      output.communicator,
      output.directory + "/contact.csv",
      [&](std::ostream &out) {
        for (unsigned int d = 0; d < dim; ++d)
          out << xyz[d] << ",";
        for (unsigned int d = 0; d < dim; ++d)
          out << "n" << xyz[d] << ",";
        out << "gap,";
        for (unsigned int d = 0; d < dim; ++d)
          out << "u" << xyz[d] << ",";
        out << "w_n,";
        for (unsigned int d = 0; d < dim; ++d)
          out << "reaction_" << xyz[d] << ",";
        out << "p_n,mu,alpha,status\n";
        out << std::setprecision(12);
        for (const unsigned int k : order)
          {
            const EquilibriumRow &row = system.rows[system.contact_rows[k]];
            for (unsigned int d = 0; d < dim; ++d)
              out << system.node_coordinates[row.node][d] << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << row.direction_component(d) << ",";
            out << row.value << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << results.reactions.contact_node_displacement[k][d] << ",";
            out << results.reactions.contact_w[k] << ",";
            for (unsigned int d = 0; d < dim; ++d)
              out << results.reactions.contact[k] * row.direction_component(d)
                  << ",";
            out << results.reactions.contact[k] << "," << contact.mu[k] << ","
                << contact.alpha[k] << ","
                << (contact.released[k] ? "open" : "contact") << "\n";
          }
      });
    write_stops_table(results, output);
    if (!Utilities::trim(tracked_nodes).empty())
      {
        // The nearest contact node of each tracked point.
        const std::vector<unsigned int> tracked =
          nearest_contact_rows(results, order, tracked_nodes);
        write_file_atomically(
          output.communicator,
          output.directory + "/contact-history.csv",
          [&](std::ostream &out) {
            out << "k,node,x,y" << (dim == 3 ? ",z" : "")
                << ",w_n,p_n,alpha,status\n"
                << std::setprecision(12);
            for (unsigned int it = 0; it < contact.p_history.size(); ++it)
              for (unsigned int t = 0; t < tracked.size(); ++t)
                {
                  const unsigned int k   = tracked[t];
                  const auto        &row = system.rows[system.contact_rows[k]];
                  out << it + 1 << "," << t + 1;
                  for (unsigned int d = 0; d < dim; ++d)
                    out << "," << system.node_coordinates[row.node][d];
                  out << "," << row.value + contact.mu_history[it][k] << ","
                      << contact.p_history[it][k] << ","
                      << contact.alpha_history[it][k] << ","
                      << (contact.released_history[it][k] ? "open" : "contact")
                      << "\n";
                }
          });
      }
    write_file_atomically(
      output.communicator,
      output.directory + "/history.csv",
      [&](std::ostream &out) {
        out
          << "k,newton_steps,alpha_min,alpha_max,eps_k,norm_pbar,active_changes,"
             "seconds\n";
        out << std::setprecision(8);
        for (const auto &h : contact.history)
          out << h.k << "," << h.newton_steps << "," << h.alpha_min << ","
              << h.alpha_max << "," << h.eps_k << "," << h.norm_pbar << ","
              << h.active_changes << "," << h.seconds << "\n";
      });
  }

  template class ContactTables<2>;
  template class ContactTables<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    ContactTables,
    "contact tables",
    70,
    "contact.csv, stops.csv, history.csv and the tracked nodes' "
    "contact-history.csv")
} // namespace hrcontact
