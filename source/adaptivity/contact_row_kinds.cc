#include <deal.II/base/tensor.h>

#include <hrcontact/adaptivity/contact_row_kinds.h>

#include <cmath>
#include <map>

namespace hrcontact
{
  using namespace dealii;

  std::string
  ContactRowKinds::not_covered(const EquilibriumSystem &sys)
  {
    if (sys.dim != 2 && !sys.contact_rows.empty())
      return "no contact in 3D yet";
    std::map<unsigned int, unsigned int> rows_at_node;
    for (const unsigned int r : sys.contact_rows)
      {
        const EquilibriumRow &row = sys.rows[r];
        if (row.law)
          return "no constraint laws (two-sided stops) so far";
        if (is_pair_row(sys, row))
          {
            if (matched_master(sys, row) == numbers::invalid_unsigned_int)
              return "contact pairs only where each slave node coincides "
                     "with a master node so far (matched meshes; not a "
                     "slave node between two master nodes)";
          }
        else if (!row.unilateral && held_dof(sys, row) < 0)
          return "bilateral rows only as normal constraints whose normal "
                 "is an axis so far (Supports/Normal displacements on "
                 "straight faces along x or y) and as contact pairs on "
                 "matched meshes";
        if (++rows_at_node[row.node] > 1)
          return "a node on two obstacles (a corner between them)";
      }
    return "";
  }

  long long
  ContactRowKinds::held_dof(const EquilibriumSystem &sys,
                            const EquilibriumRow    &row)
  {
    if (row.unilateral || row.law)
      return -1;
    long long dof = -1;
    for (unsigned int i = 0; i < row.combination.size(); ++i)
      {
        if (sys.dof_node(row.combination[i].first) != row.node)
          return -1;
        const double d = row.direction_component(i);
        if (std::abs(std::abs(d) - 1) < 1e-12)
          dof = row.combination[i].first;
        else if (std::abs(d) > 1e-12)
          return -1;
      }
    return dof;
  }

  bool
  ContactRowKinds::is_pair_row(const EquilibriumSystem &sys,
                               const EquilibriumRow    &row)
  {
    for (const auto &[dof, c] : row.combination)
      if (sys.dof_node(dof) != row.node)
        return true;
    return false;
  }

  unsigned int
  ContactRowKinds::matched_master(const EquilibriumSystem &sys,
                                  const EquilibriumRow    &row)
  {
    std::map<unsigned int, Tensor<1, 2>> at;
    for (unsigned int i = 0; i < row.combination.size(); ++i)
      if (const unsigned int node = sys.dof_node(row.combination[i].first);
          node != row.node)
        at[node][sys.dof_component(row.combination[i].first)] +=
          row.direction_component(i);
    const Tensor<1, 2> n(
      {row.direction_component(0), row.direction_component(1)});
    unsigned int master = numbers::invalid_unsigned_int;
    for (const auto &[m, d] : at)
      if ((d + n).norm() < 1e-10 && master == numbers::invalid_unsigned_int)
        master = m;
      else if (d.norm() > 1e-10)
        return numbers::invalid_unsigned_int;
    return master;
  }
} // namespace hrcontact
