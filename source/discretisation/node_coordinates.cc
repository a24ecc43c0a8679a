#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <hrcontact/discretisation/node_coordinates.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace hrcontact
{
  using namespace dealii;

  void
  NodeCoordinates::reinit(const unsigned int n)
  {
    reinit(n, 0, n);
  }

  void
  NodeCoordinates::reinit(const unsigned int n,
                          const unsigned int first,
                          const unsigned int n_owned)
  {
    AssertThrow(first + n_owned <= n,
                ExcMessage("the owned nodes lie outside the mesh's"));
    n_nodes     = n;
    first_owned = first;
    owned.assign(n_owned, Point{{0., 0., 0.}});
    others.clear();
    mean             = Point{{0., 0., 0.}};
    largest_distance = 0;
  }

  void
  NodeCoordinates::set(const unsigned int node, const Point &x)
  {
    AssertThrow(node < n_nodes,
                ExcMessage("node " + std::to_string(node) +
                           " is not one of the mesh's " +
                           std::to_string(n_nodes)));
    if (node >= first_owned && node - first_owned < owned.size())
      owned[node - first_owned] = x;
    else
      others.emplace_back(node, x);
  }

  void
  NodeCoordinates::compress(const MPI_Comm communicator)
  {
    // The first of each node's entries, in node order.
    std::stable_sort(others.begin(),
                     others.end(),
                     [](const auto &a, const auto &b) {
                       return a.first < b.first;
                     });
    others.erase(std::unique(others.begin(),
                             others.end(),
                             [](const auto &a, const auto &b) {
                               return a.first == b.first;
                             }),
                 others.end());
    others.shrink_to_fit();

    // Centre and extent over the whole mesh: the owned ranges of the
    // processes partition it (complete: the one range, in node order).
    mean = Point{{0., 0., 0.}};
    for (const auto &x : owned)
      for (unsigned int d = 0; d < 3; ++d)
        mean[d] += x[d] / n_nodes;
    if (!is_complete())
      {
        const ArrayView<const double> values(mean.data(), 3);
        const ArrayView<double>       sums(mean.data(), 3);
        Utilities::MPI::sum(values, communicator, sums);
      }
    largest_distance = 0;
    for (const auto &x : owned)
      for (unsigned int d = 0; d < 3; ++d)
        largest_distance = std::max(largest_distance, std::abs(x[d] - mean[d]));
    if (!is_complete())
      largest_distance = Utilities::MPI::max(largest_distance, communicator);
  }

  bool
  NodeCoordinates::knows(const unsigned int node) const
  {
    if (node >= first_owned && node - first_owned < owned.size())
      return true;
    return std::binary_search(others.begin(),
                              others.end(),
                              std::make_pair(node, Point{}),
                              [](const auto &a, const auto &b) {
                                return a.first < b.first;
                              });
  }

  const NodeCoordinates::Point &
  NodeCoordinates::operator[](const unsigned int node) const
  {
    if (node >= first_owned && node - first_owned < owned.size())
      return owned[node - first_owned];
    const auto it = std::lower_bound(others.begin(),
                                     others.end(),
                                     node,
                                     [](const auto &a, const unsigned int n) {
                                       return a.first < n;
                                     });
    AssertThrow(it != others.end() && it->first == node,
                ExcMessage("the coordinates of node " + std::to_string(node) +
                           " are not kept on this process (a distributed "
                           "mesh keeps its own nodes and those of the "
                           "constrained boundary)"));
    return it->second;
  }
} // namespace hrcontact
