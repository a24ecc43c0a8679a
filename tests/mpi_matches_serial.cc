// Under mpirun -np 2 the condensed path runs on a distributed mesh
// (parallel::distributed::Triangulation): each process assembles and solves
// for its own cells, the stiffness, its constraints, the AMG hierarchy and
// CG (or MUMPS for Solver = direct) are distributed, and the contact rows
// are classified from the gathered boundary faces. Each scene is solved on
// MPI_COMM_WORLD and, on every process, serially on MPI_COMM_SELF: unilateral
// contact (Hertz, lift-off, the 3D block), two-sided stops (the bridge),
// curved obstacles that follow the configuration (the cylinder) and contact
// pairs between two deformable bodies (a block on a block, two cylinders, two
// boxes in 3D), and Hertz with nested iteration (each coarser level must
// converge in both runs). The two number dofs, rows and cells differently
// (p4est orders the distributed one), so they are matched by position: the rows
// by node and direction, the nodes by coordinates, the cells by centre. They
// must give the same augmented Lagrangian history (alpha sequence to 1e-12,
// released sets, p to 1e-9 of max |p|) and the same displacements and stresses
// (each process compares its own cells). The partition must give every dof and
// cell exactly one owner and each process a share, and every contact row one
// owner (the process of its node; ContactRowPartition). The same holds on
// locally refined meshes, whose hanging nodes' equations are shared among
// their parents' rows across the processes (HangingShareForces).

#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/distributed/tria.h>

#include <algorithm>
#include <array>
#include <map>

#include "tests.h"

namespace
{
  using Key = std::array<double, 6>;

  /** Position and direction of each contact row, to match them. */
  std::vector<Key>
  row_keys(const hrcontact::EquilibriumSystem &system)
  {
    std::vector<Key> keys;
    for (const unsigned int r : system.contact_rows)
      {
        const auto &row = system.rows[r];
        Key         key{};
        for (unsigned int d = 0; d < system.dim; ++d)
          {
            key[d]     = system.node_coordinates[row.node][d];
            key[3 + d] = row.direction_component(d);
          }
        keys.push_back(key);
      }
    return keys;
  }

  /** perm[k]: the index in `b` of the item closest to a[k] (within tol),
   * or -1. */
  std::vector<int>
  match(const std::vector<Key> &a, const std::vector<Key> &b, const double tol)
  {
    std::vector<unsigned int> order(b.size());
    for (unsigned int i = 0; i < b.size(); ++i)
      order[i] = i;
    std::sort(order.begin(), order.end(), [&](unsigned int i, unsigned int j) {
      return b[i] < b[j];
    });
    std::vector<int> perm(a.size(), -1);
    for (unsigned int k = 0; k < a.size(); ++k)
      {
        // Nearest in the sorted order by the first coordinate, then scan.
        auto it = std::lower_bound(order.begin(),
                                   order.end(),
                                   a[k],
                                   [&](unsigned int i, const Key &x) {
                                     return b[i][0] < x[0] - tol;
                                   });
        for (; it != order.end() && b[*it][0] <= a[k][0] + tol; ++it)
          {
            double d = 0;
            for (unsigned int c = 0; c < 6; ++c)
              d = std::max(d, std::abs(b[*it][c] - a[k][c]));
            if (d <= tol)
              {
                perm[k] = *it;
                break;
              }
          }
      }
    return perm;
  }
} // namespace

template <int dim>
std::unique_ptr<hrcontact::HRProblem<dim>>
run(const std::string &scene, const std::string &extra, const MPI_Comm comm)
{
  return hrcontact_tests::solve_from_text<dim>(
    hrcontact_tests::condensed_scene(scene, extra), comm);
}

template <int dim>
void
compare(const std::string &scene, const std::string &extra)
{
  using dealii::Utilities::MPI::max;
  using dealii::Utilities::MPI::min;
  using dealii::Utilities::MPI::sum;
  const auto  parallel = run<dim>(scene, extra, MPI_COMM_WORLD);
  const auto  serial   = run<dim>(scene, extra, MPI_COMM_SELF);
  const auto &P        = parallel->results();
  const auto &S        = serial->results();

  const auto  &partition = P.partition;
  const auto   n_owned   = partition.owned.n_elements();
  const double n_cells =
    std::count(partition.owned_cell.begin(), partition.owned_cell.end(), true);
  const bool complete =
    sum(n_owned, MPI_COMM_WORLD) == P.system.n_displacement_dofs &&
    sum(n_cells, MPI_COMM_WORLD) == P.triangulation().n_global_active_cells();
  const bool shared = dealii::Utilities::MPI::min(n_owned, MPI_COMM_WORLD) > 0;
  const bool distributed_mesh =
    dynamic_cast<const dealii::parallel::distributed::Triangulation<dim> *>(
      &P.triangulation()) != nullptr;

  // The contact rows: each owned by the process of its node, each process
  // updating only the rows it sees (owned and ghost).
  const unsigned int n_rows = P.system.contact_rows.size();
  const bool         rows_owned_once =
    sum(P.contact->rows_owned, MPI_COMM_WORLD) == n_rows &&
    min(int(P.contact->rows_owned <= P.contact->rows_seen &&
            P.contact->rows_seen <= n_rows),
        MPI_COMM_WORLD) == 1;
  const unsigned int most_seen    = max(P.contact->rows_seen, MPI_COMM_WORLD);
  const unsigned int fewest_owned = min(P.contact->rows_owned, MPI_COMM_WORLD);
  const unsigned int most_owned   = max(P.contact->rows_owned, MPI_COMM_WORLD);

  // Length scale for matching positions.
  double size = 0;
  for (unsigned int n = 0; n < S.system.node_coordinates.size(); ++n)
    for (unsigned int d = 0; d < dim; ++d)
      size = std::max(size, std::abs(S.system.node_coordinates[n][d]));
  const double tol = 1e-10 * size;

  // The contact rows, serial k <-> parallel rows[k].
  const auto rows = match(row_keys(S.system), row_keys(P.system), tol + 1e-12);
  bool       rows_match = rows.size() == P.system.contact_rows.size();
  for (const int r : rows)
    rows_match &= (r >= 0);
  const auto &a = *S.contact, &b = *P.contact;
  bool        same_alpha =
         rows_match && a.alpha_history.size() == b.alpha_history.size(),
       same_sets = same_alpha;
  double p_max = 0, p_difference = 0;
  for (unsigned int k = 0; same_alpha && k < a.alpha_history.size(); ++k)
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        const unsigned int j = rows[i];
        same_alpha &= std::abs(a.alpha_history[k][i] - b.alpha_history[k][j]) <=
                      1e-12 * std::abs(a.alpha_history[k][i]);
        same_sets &= (a.released_history[k][i] == b.released_history[k][j]);
        p_max = std::max(p_max, std::abs(a.p_history[k][i]));
        p_difference =
          std::max(p_difference,
                   std::abs(a.p_history[k][i] - b.p_history[k][j]));
      }
  if (p_max > 0)
    p_difference /= p_max;

  // Displacements, node by node: each process its own nodes (a distributed
  // mesh keeps only their coordinates, and the distributed displacements
  // only the owned and ghost dofs), matched to the serial nodes by position.
  // Bodies in contact share positions, not nodes: the body tells them apart
  // (known at the nodes of the constrained boundary, where they touch).
  auto node_key = [](const hrcontact::EquilibriumSystem &system,
                     const unsigned int                  node) {
    const auto  &x    = system.node_coordinates[node];
    const auto   it   = system.node_body.find(node);
    const double body = it == system.node_body.end() ? -1. : it->second;
    return Key{{x[0], x[1], x[2], body, 0, 0}};
  };
  std::vector<Key>          serial_keys, own_keys;
  std::vector<unsigned int> own_nodes;
  for (unsigned int n = 0; n < S.system.node_coordinates.size(); ++n)
    serial_keys.push_back(node_key(S.system, n));
  for (unsigned int n = 0; n < P.system.node_coordinates.size(); ++n)
    if (partition.owned.is_element(dim * n))
      {
        own_nodes.push_back(n);
        own_keys.push_back(node_key(P.system, n));
      }
  const auto nodes        = match(own_keys, serial_keys, tol);
  bool       nodes_match  = sum(static_cast<double>(own_nodes.size()),
                         MPI_COMM_WORLD) == S.system.node_coordinates.size();
  double     u_difference = 0;
  for (unsigned int k = 0; k < nodes.size(); ++k)
    {
      nodes_match &= (nodes[k] >= 0);
      if (nodes[k] >= 0)
        for (unsigned int d = 0; d < dim; ++d)
          u_difference =
            std::max(u_difference,
                     std::abs(S.displacement[dim * nodes[k] + d] -
                              P.displacement[dim * own_nodes[k] + d]));
    }
  nodes_match = (min(nodes_match ? 1. : 0., MPI_COMM_WORLD) == 1.);
  u_difference =
    max(u_difference, MPI_COMM_WORLD) / S.displacement.linfty_norm();

  // Stresses, cell by cell: each process its own cells.
  std::map<std::array<double, dim>,
           typename dealii::DoFHandler<dim>::active_cell_iterator>
       serial_cells;
  auto centre = [&](const auto &cell) {
    std::array<double, dim> c;
    for (unsigned int d = 0; d < dim; ++d)
      c[d] = std::round(cell->center()[d] / tol) * tol;
    return c;
  };
  for (const auto &cell : S.spaces.dof_handler_stress.active_cell_iterators())
    serial_cells[centre(cell)] = cell;
  const unsigned int n_s = S.spaces.fe_stress->n_dofs_per_cell();
  std::vector<dealii::types::global_dof_index> ds(n_s), dp(n_s);
  double                                       s_difference = 0;
  bool                                         cells_match  = true;
  for (const auto &cell : P.spaces.dof_handler_stress.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const auto it = serial_cells.find(centre(cell));
        if (it == serial_cells.end())
          {
            cells_match = false;
            continue;
          }
        it->second->get_dof_indices(ds);
        cell->get_dof_indices(dp);
        for (unsigned int i = 0; i < n_s; ++i)
          s_difference =
            std::max(s_difference, std::abs(S.stress[ds[i]] - P.stress[dp[i]]));
      }
  s_difference = max(s_difference, MPI_COMM_WORLD) / S.stress.linfty_norm();
  cells_match  = dealii::Utilities::MPI::min(int(cells_match), MPI_COMM_WORLD);

  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout
      << scene << " (" << dim << "D, " << P.system.n_displacement_dofs
      << " dofs, " << P.solve.linear_statistics.solver << "):\n  "
      << partition.n_processes
      << " processes, distributed mesh: " << (distributed_mesh ? "yes" : "NO")
      << ", partition complete: " << (complete ? "yes" : "NO")
      << ", every process owns dofs: " << (shared ? "yes" : "NO")
      << "\n  contact rows: " << n_rows
      << ", each owned by one process: " << (rows_owned_once ? "yes" : "NO")
      << " (" << fewest_owned << " to " << most_owned << " a process), at most "
      << most_seen << " seen by one"
      << "\n  rows, nodes and cells matched by position: "
      << (rows_match && nodes_match && cells_match ? "yes" : "NO") << "\n  "
      << a.history.size() << " multiplier updates, " << a.total_newton_steps
      << " Newton steps (serial); same alpha sequence: "
      << (same_alpha ? "yes" : "NO")
      << ", same released sets: " << (same_sets ? "yes" : "NO")
      << "\n  max |p_mpi - p_serial| / max |p| over all updates < 1e-9: "
      << hrcontact_tests::check(p_difference, 1e-9)
      << "\n  displacements agree to 1e-9: "
      << hrcontact_tests::check(u_difference, 1e-9)
      << "\n  stresses agree to 1e-9: "
      << hrcontact_tests::check(s_difference, 1e-9) << std::endl;
  // Nested iteration: a coarser level that fails only costs time (the next
  // one starts from the trial solution), so say which ones converged.
  if (!S.coarse_levels.empty() &&
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      bool all_converged = P.coarse_levels.size() == S.coarse_levels.size();
      for (const auto *levels : {&P.coarse_levels, &S.coarse_levels})
        for (const auto &level : *levels)
          all_converged &= level.converged;
      std::cout << "  " << S.coarse_levels.size()
                << " coarser levels, every one converged in both runs: "
                << (all_converged ? "yes" : "NO") << std::endl;
    }
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>("hertz.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<2>("lift-off.prm",
             "subsection Linear solver\n  set Solver = direct\nend\n");
  // Nested iteration with MUMPS on the distributed coarser levels (a
  // penalty growth there once left the coarsest held by springs alone,
  // which MUMPS refused as singular).
  compare<2>("hertz.prm",
             "subsection Geometry\n  set Global refinements = 5\nend\n"
             "subsection Nested iteration\n  set Coarse levels = 2\nend\n"
             "subsection Linear solver\n  set Solver = direct\nend\n");
  compare<2>("bridge-stops.prm",
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<2>("cylinder-indentation.prm",
             "subsection Geometry\n  set Global refinements = 4\nend\n"
             "subsection Linear solver\n  set Solver = direct\nend\n");
  // Contact between two deformable bodies: p4est puts each body on its
  // own process, so every pair row spans both.
  compare<2>("stacked-blocks-lift-off.prm",
             "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
             "subsection Linear solver\n  set Solver = direct\nend\n");
  // The same with the lifting part tethered (a two-sided stop on the
  // pair: opening 1e-6, then a stiffness branch).
  compare<2>("stacked-blocks-lift-off.prm",
             "subsection Equilibrium reduction\n  set Path = condensed\nend\n"
             "subsection Contact\n  set Pair laws = 12: stop : -1e-6 : 0 : "
             "-1e20 : 1e3 : 0 : 1e10\nend\n"
             "subsection Linear solver\n  set Solver = direct\nend\n");
  compare<2>("two-cylinders.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<2>("two-cylinders.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n"
             "subsection Contact\n  set Pair method = mortar\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<3>("stacked-boxes-3d.prm",
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<3>("stacked-boxes-3d.prm",
             "subsection Contact\n  set Pair method = mortar\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<3>("block-3d-contact.prm",
             "subsection Geometry\n  set Global refinements = 1\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  // Locally refined meshes (hanging nodes): the cells around a hanging node
  // may be on another process than its parents' rows. Hertz refined at its
  // contact zone, with AMG and with MUMPS, and the 3D block refined at
  // part of its base, where hanging nodes lie on the contact face.
  const std::string hertz_region =
    "subsection Mesh refinement\n"
    "  set Refinement region = -0.001, -0.051 : 0.015, -0.043\n"
    "  set Region refinements = 2\nend\n";
  compare<2>("hertz.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n" +
               hertz_region +
               "subsection Linear solver\n  set Solver = cg-amg\nend\n");
  compare<2>("hertz.prm",
             "subsection Geometry\n  set Global refinements = 3\nend\n" +
               hertz_region +
               "subsection Linear solver\n  set Solver = direct\nend\n");
  compare<3>("block-3d-contact.prm",
             "subsection Geometry\n  set Global refinements = 1\nend\n"
             "subsection Mesh refinement\n"
             "  set Refinement region = 0.9, 0.9, -0.1 : 2.1, 2.1, 0.3\n"
             "  set Region refinements = 1\nend\n"
             "subsection Linear solver\n  set Solver = cg-amg\nend\n");
}
