#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/discretisation/equilibrium_system.h>

#include <algorithm>
#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  ContactRowPartition::ContactRowPartition(const unsigned int n_rows)
    : n(n_rows)
    , owned_set(complete_index_set(n_rows))
  {
    owned_rows.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      owned_rows[i] = i;
    relevant_rows = owned_rows;
  }

  ContactRowPartition::ContactRowPartition(const EquilibriumSystem &system,
                                           const DofPartition      &partition)
    : ContactRowPartition(system.contact_rows.size())
  {
    // Without rows there is nothing to share (and deal.II's dictionary of
    // owners cannot be built over an empty range).
    if (!partition.distributed() || n == 0)
      return;
    whole        = false;
    communicator = partition.communicator;
    owned_rows.clear();
    relevant_rows.clear();
    owned_set = IndexSet(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto dof =
          system.rows[system.contact_rows[i]].combination.front().first;
        if (partition.owned.is_element(dof))
          {
            owned_rows.push_back(i);
            relevant_rows.push_back(i);
          }
        else if (partition.relevant.is_element(dof))
          {
            ghost_rows.push_back(i);
            relevant_rows.push_back(i);
          }
      }
    owned_set.add_indices(owned_rows.begin(), owned_rows.end());
    owned_set.compress();
    // Every row has exactly one owner, or its p would be lost or doubled.
    AssertThrow(sum(static_cast<unsigned int>(owned_rows.size())) == n,
                ExcInternalError());
    exchange = std::make_shared<Utilities::MPI::NoncontiguousPartitioner>(
      std::vector<types::global_dof_index>(owned_rows.begin(),
                                           owned_rows.end()),
      std::vector<types::global_dof_index>(ghost_rows.begin(),
                                           ghost_rows.end()),
      communicator);
  }

  void
  ContactRowPartition::import_ghosts(std::vector<double> &v) const
  {
    if (whole)
      return;
    AssertDimension(v.size(), n);
    std::vector<double> owned_values(owned_rows.size()),
      ghost_values(ghost_rows.size());
    for (unsigned int k = 0; k < owned_rows.size(); ++k)
      owned_values[k] = v[owned_rows[k]];
    exchange->export_to_ghosted_array(
      ArrayView<const double>(owned_values.data(), owned_values.size()),
      ArrayView<double>(ghost_values.data(), ghost_values.size()));
    for (unsigned int k = 0; k < ghost_rows.size(); ++k)
      v[ghost_rows[k]] = ghost_values[k];
  }

  void
  ContactRowPartition::gather(std::vector<double> &v) const
  {
    if (whole)
      return;
    AssertDimension(v.size(), n);
    std::vector<double> mine(n, 0.);
    for (const unsigned int i : owned_rows)
      mine[i] = v[i];
    Utilities::MPI::sum(mine, communicator, v);
  }

  void
  ContactRowPartition::gather(std::vector<bool> &v) const
  {
    if (whole)
      return;
    std::vector<double> values(n, 0.);
    for (const unsigned int i : owned_rows)
      values[i] = v[i];
    gather(values);
    for (unsigned int i = 0; i < n; ++i)
      v[i] = (values[i] != 0);
  }

  double
  ContactRowPartition::sum(const double x) const
  {
    return whole ? x : Utilities::MPI::sum(x, communicator);
  }

  unsigned int
  ContactRowPartition::sum(const unsigned int x) const
  {
    return whole ? x : Utilities::MPI::sum(x, communicator);
  }

  double
  ContactRowPartition::max(const double x) const
  {
    return whole ? x : Utilities::MPI::max(x, communicator);
  }

  double
  ContactRowPartition::min(const double x) const
  {
    return whole ? x : Utilities::MPI::min(x, communicator);
  }

  bool
  ContactRowPartition::all(const bool x) const
  {
    return whole ? x : (Utilities::MPI::min(x ? 1u : 0u, communicator) == 1);
  }

  std::vector<bool>
  ContactRowPartition::all(const std::vector<bool> &x) const
  {
    if (whole)
      return x;
    std::vector<unsigned int> values(x.begin(), x.end());
    Utilities::MPI::min(values, communicator, values);
    return std::vector<bool>(values.begin(), values.end());
  }

  double
  ContactRowPartition::norm(const std::vector<double> &v) const
  {
    double squares = 0;
    for (const unsigned int i : owned_rows)
      squares += v[i] * v[i];
    return std::sqrt(sum(squares));
  }
} // namespace hrcontact
