// The held rows of the condensed path as constraints (solvers/condensed/
// held_rows.h): one row d . u = value expresses its largest |d_k| by the
// others; several rows at one node (a corner between obstacles, eq. 11) are
// eliminated jointly by Gauss-Jordan. For a 2D corner, a 3D corner and a 3D
// edge (two rows, one direction free), and a prescribed row meeting an
// obstacle row, the distributed displacement must satisfy every row to
// round-off for arbitrary free values, each constrained dof must be
// expressed by free dofs only (no chains), and rows with parallel normals
// must be an InputError naming the node.

#include <deal.II/base/mpi.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/held_rows.h>

#include <cmath>
#include <iostream>
#include <random>

#include "tests.h"

using namespace dealii;
using hrcontact::EquilibriumRow;

/** A row at node 7 over dofs first, first + 1, ... with direction d. */
EquilibriumRow
row(const unsigned int first, const std::vector<double> &d, const double g)
{
  EquilibriumRow r;
  for (unsigned int k = 0; k < d.size(); ++k)
    r.combination.emplace_back(first + k, d[k]);
  r.direction = d;
  r.value     = g;
  r.node      = 7;
  return r;
}

std::vector<double>
unit(std::vector<double> d)
{
  double norm = 0;
  for (const double x : d)
    norm += x * x;
  for (double &x : d)
    x /= std::sqrt(norm);
  return d;
}

/** Constrain @p rows (jointly when several), fill the free dofs with random
 * values, distribute, and report the largest row residual and whether a
 * constrained dof depends on another one. */
void
check_rows(const std::string                 &name,
           const std::vector<EquilibriumRow> &rows,
           const unsigned int                 n_dofs,
           std::mt19937                      &random)
{
  AffineConstraints<double>       constraints;
  std::vector<hrcontact::HeldRow> held;
  for (const auto &r : rows)
    held.emplace_back(&r, r.value);
  if (held.size() == 1)
    hrcontact::constrain_row(rows[0], rows[0].value, constraints);
  else
    hrcontact::constrain_jointly(held, constraints, [](const unsigned int n) {
      return "node " + std::to_string(n);
    });
  constraints.close();

  bool chained = false;
  for (const auto &line : constraints.get_lines())
    for (const auto &[dof, coefficient] : line.entries)
      chained = chained || constraints.is_constrained(dof);

  std::uniform_real_distribution<double> uniform(-1., 1.);
  double                                 residual = 0;
  for (unsigned int trial = 0; trial < 5; ++trial)
    {
      Vector<double> u(n_dofs);
      for (auto &x : u)
        x = uniform(random);
      constraints.distribute(u);
      for (const auto &r : rows)
        {
          double w = 0;
          for (unsigned int k = 0; k < r.combination.size(); ++k)
            w += r.direction_component(k) * u[r.combination[k].first];
          residual = std::max(residual, std::abs(w - r.value));
        }
    }
  std::cout << name << ": " << constraints.n_constraints()
            << " dofs constrained"
            << "\n  max |d . u - value| <= 1e-14: "
            << hrcontact_tests::check(residual, 1e-14)
            << "\n  constrained dofs expressed by free dofs only: "
            << (chained ? "NO" : "yes") << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::mt19937                     random(5);

  check_rows("one inclined row", {row(0, unit({0.3, -0.8}), 0.2)}, 2, random);
  check_rows("2D corner, walls at 30 and 100 degrees",
             {row(0, {std::cos(0.52), std::sin(0.52)}, 0.1),
              row(0, {std::cos(1.75), std::sin(1.75)}, -0.05)},
             2,
             random);
  check_rows("3D corner, three oblique walls",
             {row(0, unit({1, 0.2, 0.1}), 0.01),
              row(0, unit({0.1, 1, -0.3}), 0.02),
              row(0, unit({0.2, 0.4, 1}), -0.03)},
             3,
             random);
  check_rows("3D edge, two walls (one direction free)",
             {row(0, unit({1, 1, 0}), 0.01), row(0, unit({0, 1, 1}), 0.02)},
             3,
             random);
  // A support (u_y = 0.1) and an inclined obstacle at one node; the rows'
  // dofs after those of another node (a global numbering).
  check_rows("prescribed u_y and an obstacle row",
             {row(4, {0, 1}, 0.1), row(4, unit({1, -0.5}), 0.05)},
             6,
             random);

  // Parallel normals: the second row adds nothing.
  try
    {
      AffineConstraints<double>         constraints;
      const std::vector<EquilibriumRow> rows = {row(0, unit({1, 1}), 0.),
                                                row(0, unit({-2, -2}), 0.)};
      hrcontact::constrain_jointly({{&rows[0], 0.}, {&rows[1], 0.}},
                                   constraints,
                                   [](const unsigned int n) {
                                     return "node " + std::to_string(n);
                                   });
      std::cout << "parallel normals: no error" << std::endl;
    }
  catch (const hrcontact::InputError &e)
    {
      std::cout << "parallel normals: " << e.what() << std::endl;
    }
}
