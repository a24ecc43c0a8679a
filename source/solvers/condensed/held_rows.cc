#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/held_rows.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  void
  constrain_row(const EquilibriumRow      &row,
                const double               value,
                AffineConstraints<double> &constraints)
  {
    unsigned int k_max = 0;
    for (unsigned int k = 1; k < row.combination.size(); ++k)
      if (std::abs(row.direction_component(k)) >
          std::abs(row.direction_component(k_max)))
        k_max = k;
    const auto   dof = row.combination[k_max].first;
    const double d   = row.direction_component(k_max);
    constraints.add_line(dof);
    for (unsigned int k = 0; k < row.combination.size(); ++k)
      if (k != k_max && row.direction_component(k) != 0)
        constraints.add_entry(dof,
                              row.combination[k].first,
                              -row.direction_component(k) / d);
    constraints.set_inhomogeneity(dof, value / d);
  }

  void
  constrain_jointly(
    const std::vector<HeldRow>                           &rows,
    AffineConstraints<double>                            &constraints,
    const std::function<std::string(const unsigned int)> &describe_node)
  {
    const auto        &dofs = rows.front().first->combination;
    const unsigned int m = rows.size(), n = dofs.size();
    FullMatrix<double> D(m, n);
    Vector<double>     b(m);
    for (unsigned int r = 0; r < m; ++r)
      {
        for (unsigned int k = 0; k < n; ++k)
          D(r, k) = rows[r].first->direction_component(k);
        b[r] = rows[r].second;
      }
    std::vector<unsigned int> pivot(m);
    std::vector<bool>         is_pivot(n, false);
    for (unsigned int r = 0; r < m; ++r)
      {
        unsigned int c = n;
        for (unsigned int k = 0; k < n; ++k)
          if (!is_pivot[k] && (c == n || std::abs(D(r, k)) > std::abs(D(r, c))))
            c = k;
        if (c == n || std::abs(D(r, c)) < 1e-10)
          throw InputError(
            "the constraints held at " + describe_node(rows[r].first->node) +
            " are linearly dependent (obstacles with parallel normals?).");
        pivot[r]           = c;
        is_pivot[c]        = true;
        const double scale = D(r, c);
        for (unsigned int k = 0; k < n; ++k)
          D(r, k) /= scale;
        b[r] /= scale;
        for (unsigned int s = 0; s < m; ++s)
          if (s != r && D(s, c) != 0)
            {
              const double factor = D(s, c);
              for (unsigned int k = 0; k < n; ++k)
                D(s, k) -= factor * D(r, k);
              b[s] -= factor * b[r];
            }
      }
    for (unsigned int r = 0; r < m; ++r)
      {
        constraints.add_line(dofs[pivot[r]].first);
        for (unsigned int k = 0; k < n; ++k)
          if (!is_pivot[k] && D(r, k) != 0)
            constraints.add_entry(dofs[pivot[r]].first,
                                  dofs[k].first,
                                  -D(r, k));
        constraints.set_inhomogeneity(dofs[pivot[r]].first, b[r]);
      }
  }
} // namespace hrcontact
