#include <deal.II/base/mpi.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/held_rows.h>
#include <hrcontact/solvers/condensed/step_rows.h>

#include <map>
#include <string>

namespace hrcontact
{
  using namespace dealii;

  void
  Spring::matrix_and_force(FullMatrix<double> &matrix,
                           Vector<double>     &force) const
  {
    const unsigned int n   = row->combination.size();
    const double       k_s = 1. / piece->compliance;
    matrix.reinit(n, n);
    force.reinit(n);
    for (unsigned int a = 0; a < n; ++a)
      {
        force[a] =
          row->direction_component(a) * k_s * (row->value + piece->offset);
        for (unsigned int b = 0; b < n; ++b)
          matrix(a, b) =
            k_s * row->direction_component(a) * row->direction_component(b);
      }
  }

  StepRows::StepRows(const EquilibriumSystem         &system,
                     const DofPartition              &partition,
                     const ContactRowPartition       &row_ownership,
                     const std::vector<ContactPiece> &pieces)
    : constraints(partition.relevant)
  {
    // The dofs of a node all belong to the same process.
    auto relevant = [&](const EquilibriumRow &row) {
      return partition.relevant.is_element(row.combination.front().first);
    };
    // The hanging nodes follow their parents in every solve.
    for (const auto &line : system.hanging_nodes.get_lines())
      {
        constraints.add_line(line.index);
        constraints.add_entries(line.index, line.entries);
      }
    // Held rows per node: the prescribed ones and the held Q rows; springs.
    std::map<unsigned int, std::vector<HeldRow>> held;
    std::map<unsigned int, unsigned int>         held_q_rows;
    for (const unsigned int r : system.prescribed_rows)
      if (relevant(system.rows[r]))
        held[system.rows[r].node].emplace_back(&system.rows[r],
                                               system.rows[r].value);
    for (const unsigned int i : row_ownership.relevant())
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        if (!pieces[i].spring)
          {
            held[row.node].emplace_back(&row, row.value + pieces[i].offset);
            ++held_q_rows[row.node];
          }
        else if (row_ownership.is_owned(i))
          springs.push_back({&row, &pieces[i]});
      }
    // A process sees only its relevant nodes: an error found at one of
    // them must stop every process, or the others would wait in the
    // assembly's communication.
    std::string error;
    try
      {
        const auto describe_node = [&](const unsigned int node) {
          return system.describe_node(node);
        };
        for (const auto &[node, rows] : held)
          if (held_q_rows[node] > 1)
            constrain_jointly(rows, constraints, describe_node);
          else
            for (const auto &[row, value] : rows)
              constrain_row(*row, value, constraints);
      }
    catch (const InputError &e)
      {
        error = e.what();
      }
    if (partition.distributed())
      for (const auto &e :
           Utilities::MPI::all_gather(partition.communicator, error))
        if (error.empty())
          error = e;
    if (!error.empty())
      throw InputError(error);
    constraints.close();

    key.reserve(row_ownership.relevant().size() * (1 + system.dim));
    for (const unsigned int i : row_ownership.relevant())
      {
        const EquilibriumRow &row = system.rows[system.contact_rows[i]];
        key.push_back(pieces[i].spring ? pieces[i].compliance : -1.);
        for (unsigned int k = 0; k < row.combination.size(); ++k)
          key.push_back(row.direction_component(k));
      }
  }
} // namespace hrcontact
