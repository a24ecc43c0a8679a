#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <hrcontact/geometry/cell_aspect_ratio.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  double
  largest_cell_aspect_ratio(const Triangulation<dim> &triangulation)
  {
    double largest = 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // At the centre, column d of the Jacobian of the Q1 map is the mean
          // of the cell's edges along d (vertices numbered lexicographically).
          Tensor<2, dim> J;
          for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell;
               ++v)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double sign = (v & (1u << d)) ? 1. : -1.;
                for (unsigned int i = 0; i < dim; ++i)
                  J[i][d] += sign * cell->vertex(v)[i];
              }
          // The singular values are the square roots of J^T J's eigenvalues.
          const auto   lambda = eigenvalues(symmetrize(transpose(J) * J));
          const double lmax   = lambda[0];
          const double lmin   = lambda[dim - 1];
          largest =
            std::max(largest,
                     lmin > 0 ? std::sqrt(lmax / lmin) :
                                std::numeric_limits<double>::infinity());
        }
    return Utilities::MPI::max(largest, triangulation.get_communicator());
  }

  template double
  largest_cell_aspect_ratio(const Triangulation<2> &);
  template double
  largest_cell_aspect_ratio(const Triangulation<3> &);
} // namespace hrcontact
