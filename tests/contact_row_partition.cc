// ContactRowPartition on 3 processes, by hand: 12 Q rows at the nodes of a
// chain of 12 one-dof nodes, process k owning the dofs 4k to 4k + 3 and
// seeing its neighbours' nearest dof as a ghost (as a layer of ghost cells
// would). Each row must belong to the owner of its node and be seen by the
// processes whose relevant dofs hold it; import_ghosts must give a ghost row
// its owner's value, gather the complete vector on every process, and the
// norm, sums and agreements must be those of all rows once. A process owns
// its rows whatever their order in contact_rows (here reversed).

#include <deal.II/base/mpi.h>

#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/discretisation/dof_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  std::string
  yes(const bool ok)
  {
    return ok ? "yes" : "NO";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const unsigned int me = dealii::Utilities::MPI::this_mpi_process(comm);
  const unsigned int np = dealii::Utilities::MPI::n_mpi_processes(comm);
  const unsigned int n  = 4 * np;

  hrcontact::DofPartition partition;
  partition.communicator = comm;
  partition.n_processes  = np;
  partition.process      = me;
  partition.owned        = dealii::IndexSet(n);
  partition.owned.add_range(4 * me, 4 * me + 4);
  partition.relevant = partition.owned;
  if (me > 0)
    partition.relevant.add_index(4 * me - 1);
  if (me + 1 < np)
    partition.relevant.add_index(4 * me + 4);

  // Row i at dof 11 - i: contact_rows in the reverse order of the dofs.
  hrcontact::EquilibriumSystem system;
  for (unsigned int i = 0; i < n; ++i)
    {
      hrcontact::EquilibriumRow row;
      row.row_class   = hrcontact::RowClass::contact;
      row.combination = {{n - 1 - i, 1.}};
      system.rows.push_back(row);
      system.contact_rows.push_back(i);
    }
  const hrcontact::ContactRowPartition rows(system, partition);

  auto owner = [](const unsigned int i, const unsigned int n) {
    return (n - 1 - i) / 4;
  };
  // Owned and relevant rows as the dofs say.
  bool owned_right = true, seen_right = true;
  for (unsigned int i = 0; i < n; ++i)
    {
      const auto dof = n - 1 - i;
      owned_right &= (rows.is_owned(i) == (owner(i, n) == me));
      const bool seen =
        std::find(rows.relevant().begin(), rows.relevant().end(), i) !=
        rows.relevant().end();
      seen_right &= (seen == partition.relevant.is_element(dof));
    }
  const bool         all_owned_right = rows.all(owned_right);
  const bool         all_seen_right  = rows.all(seen_right);
  const unsigned int n_owned =
    rows.sum(static_cast<unsigned int>(rows.owned().size()));

  // The owners' values reach the ghost rows; nothing else is written.
  std::vector<double> v(n, -1.);
  for (const unsigned int i : rows.owned())
    v[i] = 100. * i + 1;
  rows.import_ghosts(v);
  bool imported = true;
  for (unsigned int i = 0; i < n; ++i)
    {
      const bool seen = partition.relevant.is_element(n - 1 - i);
      imported &= seen ? (v[i] == 100. * i + 1) : (v[i] == -1.);
    }
  imported = rows.all(imported);

  // gather: the complete vector everywhere, from the owners alone (the
  // others' entries must not count).
  std::vector<double> w(n, 0.);
  for (unsigned int i = 0; i < n; ++i)
    w[i] = rows.is_owned(i) ? 10. * i : 1e6;
  rows.gather(w);
  bool gathered = true;
  for (unsigned int i = 0; i < n; ++i)
    gathered &= (w[i] == 10. * i);
  gathered = rows.all(gathered);
  std::vector<bool> flags(n, false);
  for (const unsigned int i : rows.owned())
    flags[i] = (i % 3 == 0);
  rows.gather(flags);
  bool flags_gathered = true;
  for (unsigned int i = 0; i < n; ++i)
    flags_gathered &= (flags[i] == (i % 3 == 0));
  flags_gathered = rows.all(flags_gathered);

  // The norm over the owned rows, each once: of w (complete now), the
  // norm of 10 i over all rows.
  double squares = 0;
  for (unsigned int i = 0; i < n; ++i)
    squares += 100. * i * i;
  const double norm_error = std::abs(rows.norm(w) - std::sqrt(squares));

  // Element-wise agreement: entry j (< np) fails on process j alone, so
  // on no entry do all agree; the last entry holds everywhere.
  std::vector<bool> x(np + 1, true);
  x[me]                                   = false;
  const std::vector<bool> a               = rows.all(x);
  bool                    agreement_right = a.size() == np + 1 && a[np];
  for (unsigned int j = 0; j < np; ++j)
    agreement_right &= !a[j];

  // One process: every row owned, nothing communicated.
  const hrcontact::ContactRowPartition whole(n);
  const bool whole_right = !whole.distributed() && whole.owned().size() == n &&
                           whole.relevant().size() == n;

  if (me == 0)
    std::cout << np << " processes, " << n << " rows\n"
              << "rows owned by the owner of their node: "
              << yes(all_owned_right && n_owned == n)
              << "\nrows seen where their node is relevant: "
              << yes(all_seen_right)
              << "\nghost rows get the owner's value, others untouched: "
              << yes(imported)
              << "\ngather: every entry from its owner: " << yes(gathered)
              << ", flags too: " << yes(flags_gathered)
              << "\nnorm over the owned rows, each once: "
              << yes(norm_error <= 1e-12 * std::sqrt(squares))
              << "\nelement-wise agreement: " << yes(agreement_right)
              << "\none process: every row owned: " << yes(whole_right)
              << std::endl;
}
