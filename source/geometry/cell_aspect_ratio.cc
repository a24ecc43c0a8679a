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
          // The singular values are the square roots of J^T J's eigenvalues;
          // an inverted or degenerate cell has no finite ratio.
          const double det = determinant(J);
          double       ratio;
          if (!(det > 0))
            ratio = std::numeric_limits<double>::infinity();
          else if (dim == 2)
            {
              // s1^2 + s2^2 = |J|^2 and s1 s2 = det: ratio + 1/ratio = q,
              // without the cancellation of an eigenvalue formula on
              // square cells (which gave no value on a 0.0125 m cell).
              const double q = J.norm_square() / det;
              ratio          = 0.5 * (q + std::sqrt(std::max(q * q - 4, 0.)));
            }
          else
            {
              const auto lambda = eigenvalues(symmetrize(transpose(J) * J));
              // The smallest from the product of all three, det^2.
              ratio =
                std::sqrt(lambda[0] * lambda[0] * lambda[1] / (det * det));
            }
          largest = std::max(largest, ratio);
        }
    return Utilities::MPI::max(largest, triangulation.get_communicator());
  }

  template double
  largest_cell_aspect_ratio(const Triangulation<2> &);
  template double
  largest_cell_aspect_ratio(const Triangulation<3> &);
} // namespace hrcontact
