#include <hrcontact/discretisation/hanging_nodes.h>
#include <hrcontact/postprocess/balance_report.h>
#include <hrcontact/postprocess/sorted_rows.h>

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    /** Two-sided stops: which node sits on which branch of its law. */
    template <int dim>
    void
    report_stop_branches(const Results<dim> &results, Summary &summary)
    {
      const EquilibriumSystem &system  = results.system;
      const ContactIteration  &contact = *results.contact;
      std::map<unsigned int, std::pair<unsigned int, std::string>> branches;
      bool                                                         any = false;
      for (const unsigned int k : sorted_stop_rows(system))
        {
          any = true;
          const auto &c =
            system.node_coordinates[system.rows[system.contact_rows[k]].node];
          auto              &entry = branches[contact.pieces[k].branch];
          std::ostringstream where;
          where << std::setprecision(6) << " (" << c[0];
          for (unsigned int d = 1; d < dim; ++d)
            where << ", " << c[d];
          where << ")";
          ++entry.first;
          entry.second += where.str();
        }
      if (any)
        {
          const char *keys[5] = {"stops_free",
                                 "stops_at_upper_stop",
                                 "stops_beyond_upper",
                                 "stops_at_lower_stop",
                                 "stops_beyond_lower"};
          for (unsigned int b = 0; b < 5; ++b)
            {
              const auto it = branches.find(b);
              summary.add(keys[b],
                          it == branches.end() ?
                            std::string("0") :
                            std::to_string(it->second.first) + " at" +
                              it->second.second);
            }
        }
    }

    /** The Signorini conditions on the unilateral rows (eq. 12) and the
     * stops' branches. */
    template <int dim>
    void
    report_contact_conditions(const Results<dim> &results, Summary &summary)
    {
      const EquilibriumSystem &system  = results.system;
      const ContactIteration  &contact = *results.contact;
      // Signorini conditions on the unilateral rows (eq. 12).
      double max_p_positive = 0, max_penetration = 0, max_complementarity = 0;
      unsigned int pressed = 0;
      for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
        if (system.rows[system.contact_rows[k]].unilateral)
          {
            const double p   = results.reactions.contact[k];
            const double gap = results.reactions.contact_w[k] -
                               system.rows[system.contact_rows[k]].value;
            max_p_positive  = std::max(max_p_positive, p);
            max_penetration = std::max(max_penetration, gap);
            max_complementarity =
              std::max(max_complementarity, std::abs(p * gap));
            pressed += !contact.released[k];
          }
      summary.add("pressed_constraints", pressed);
      summary.add("final_norm_pbar", contact.final_norm_pbar);
      summary.add("tolerance", contact.tolerance_used);
      summary.add("max_positive_p_n", max_p_positive);
      summary.add("max_penetration", max_penetration);
      summary.add("max_complementarity", max_complementarity);

      report_stop_branches(results, summary);
    }
  } // namespace

  template <int dim>
  void
  BalanceReport<dim>::execute(const Results<dim> &results,
                              PostprocessOutput  &output)
  {
    const EquilibriumSystem &system  = results.system;
    Summary                 &summary = output.summary;
    std::ostream            &log     = output.log;

    // Global balance: the reactions (forces the supports exert on the body)
    // and the applied loads sum to zero to round-off.
    // Scale: the largest nodal force involved, so that a self-balanced
    // problem (zero net load) is judged against its reactions.
    std::vector<double> load(dim, 0.), reaction(dim, 0.);
    double              scale = 0;
    // The directions d_r of a node are the primal basis to the dual basis
    // c_r of the rows: sum_r (f.c_r) d_r = f.
    // A distributed load vector holds the owned and ghost dofs: each
    // process sums the loads of the nodes it owns, and the sums are added.
    const bool distributed = !is_complete(system.load);
    auto       mine        = [&](const types::global_dof_index i) {
      return !distributed || results.partition.owned.is_element(i);
    };
    std::vector<bool> stored(system.lean_rows ? system.n_displacement_dofs : 0,
                             false);
    for (const auto &row : system.rows)
      {
        if (system.lean_rows)
          for (const auto &[dof, c] : row.combination)
            stored[dof] = true;
        if (!mine(row.combination.front().first))
          continue;
        const double f_r = system.row_load(row);
        scale            = std::max(scale, std::abs(f_r));
        // A row may span several nodes (contact pairs): by component.
        for (unsigned int k = 0; k < row.combination.size(); ++k)
          load[system.dof_component(row.combination[k].first)] +=
            f_r * row.direction_component(k);
      }
    // Lean rows: the implicit free rows are the unit rows of the other dofs,
    // each carrying its hanging children's shares (an explicit row has its
    // own, EquilibriumRow::shares); a hanging dof has no row.
    std::vector<double> shares(stored.size(), 0.);
    for (const auto &line : system.hanging_nodes.get_lines())
      for (const auto &[parent, a] : line.entries)
        if (parent < shares.size())
          shares[parent] += a * system.load[line.index];
    for (unsigned int i = 0; i < stored.size(); ++i)
      if (!stored[i] && mine(i) && !is_hanging(system, i))
        {
          const double f_i = system.load[i] + shares[i];
          scale            = std::max(scale, std::abs(f_i));
          load[system.dof_component(i)] += f_i;
        }
    if (distributed)
      {
        Utilities::MPI::sum(load, results.partition.communicator, load);
        scale = Utilities::MPI::max(scale, results.partition.communicator);
      }
    auto add_reaction = [&](const unsigned int r, const double value) {
      scale                     = std::max(scale, std::abs(value));
      const EquilibriumRow &row = system.rows[r];
      for (unsigned int k = 0; k < row.combination.size(); ++k)
        reaction[system.dof_component(row.combination[k].first)] +=
          value * row.direction_component(k);
    };
    for (unsigned int k = 0; k < system.contact_rows.size(); ++k)
      add_reaction(system.contact_rows[k], results.reactions.contact[k]);
    for (unsigned int k = 0; k < system.prescribed_rows.size(); ++k)
      add_reaction(system.prescribed_rows[k], results.reactions.support[k]);
    double      imbalance = 0;
    const char *xyz       = "xyz";
    for (unsigned int d = 0; d < dim; ++d)
      {
        summary.add(std::string("total_load_") + xyz[d], load[d]);
        summary.add(std::string("total_reaction_") + xyz[d], reaction[d]);
        imbalance = std::max(imbalance, std::abs(load[d] + reaction[d]));
      }
    summary.add("equilibrium_imbalance",
                scale > 0 ? imbalance / scale : imbalance);
    double max_p = 0;
    for (const double p : results.reactions.contact)
      max_p = std::max(max_p, std::abs(p));
    summary.add("max_abs_p_n", max_p);
    if (results.contact)
      report_contact_conditions(results, summary);
    // Over the processes on a distributed mesh.
    const double max_u = results.displacement.linfty_norm();
    summary.add("max_abs_displacement_component", max_u);

    log << "  total load     (";
    for (unsigned int d = 0; d < dim; ++d)
      log << (d ? ", " : "") << std::setprecision(6) << load[d];
    log << ")\n  total reaction (";
    for (unsigned int d = 0; d < dim; ++d)
      log << (d ? ", " : "") << std::setprecision(6) << reaction[d];
    log << ")" << std::endl;
  }

  template class BalanceReport<2>;
  template class BalanceReport<3>;

  HRCONTACT_REGISTER_POSTPROCESSOR(
    BalanceReport,
    "balance",
    10,
    "total load and reaction, equilibrium imbalance, Signorini residuals, "
    "the branches of two-sided stops")
} // namespace hrcontact
