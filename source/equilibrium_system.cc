#include <hrcontact/equilibrium_system.h>

#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  double
  EquilibriumSystem::row_times(const EquilibriumRow &row,
                               const Vector<double> &s) const
  {
    double sum = 0;
    for (const auto &[dof, c] : row.combination)
      for (auto it = B.begin(dof); it != B.end(dof); ++it)
        sum += c * it->value() * s[it->column()];
    return sum;
  }

  void
  EquilibriumSystem::add_row_transpose(const EquilibriumRow &row,
                                       const double          coefficient,
                                       Vector<double>       &v) const
  {
    for (const auto &[dof, c] : row.combination)
      for (auto it = B.begin(dof); it != B.end(dof); ++it)
        v[it->column()] += coefficient * c * it->value();
  }

  double
  EquilibriumSystem::row_load(const EquilibriumRow &row) const
  {
    double sum = 0;
    for (const auto &[dof, c] : row.combination)
      sum += c * load[dof];
    return sum;
  }

  void
  EquilibriumSystem::multiply_flexibility(const Vector<double> &s,
                                          Vector<double>       &Fs) const
  {
    Fs.reinit(n_stress_dofs);
    for (unsigned int c = 0; c < cell_stress_dofs.size(); ++c)
      {
        const auto &dofs = cell_stress_dofs[c];
        const auto &Fc   = cell_flexibility[c];
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            double sum = 0;
            for (unsigned int j = 0; j < dofs.size(); ++j)
              sum += Fc(i, j) * s[dofs[j]];
            Fs[dofs[i]] += sum;
          }
      }
  }

  void
  EquilibriumSystem::displacements_from_row_values(
    const std::vector<double> &row_values,
    Vector<double>            &u) const
  {
    u.reinit(n_displacement_dofs);
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto &[dof, c] : rows[r].combination)
        u[dof] += row_values[r] * c;
  }

  std::string
  EquilibriumSystem::describe_node(const unsigned int node) const
  {
    std::ostringstream s;
    s << std::setprecision(6) << "node (";
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << node_coordinates[node][d];
    s << ")";
    return s.str();
  }

  std::string
  EquilibriumSystem::describe_row(const unsigned int r) const
  {
    const EquilibriumRow &row = rows[r];
    std::ostringstream    s;
    s << describe_node(row.node) << " direction (";
    std::vector<double> dir(dim, 0.);
    // The combination holds the node's dofs in component order.
    for (unsigned int k = 0; k < row.combination.size(); ++k)
      dir[k] = row.combination[k].second;
    for (unsigned int d = 0; d < dim; ++d)
      s << (d ? ", " : "") << std::setprecision(3) << dir[d];
    s << ")";
    return s.str();
  }
} // namespace hrcontact
