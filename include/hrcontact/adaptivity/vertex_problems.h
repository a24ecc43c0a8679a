#ifndef hrcontact_vertex_problems_h
#define hrcontact_vertex_problems_h

#include <deal.II/lac/full_matrix.h>

#include <hrcontact/core/results.h>

#include <map>
#include <vector>

namespace hrcontact
{
  /** Per active cell: whether this process holds its stresses and
   * displacements (its own cells and its ghosts), so that the vertex
   * problems of its own cells' vertices need no more (the face tractions
   * of the error bound, 2D and 3D). */
  template <int dim>
  std::vector<bool>
  cells_held_whole(const Results<dim> &results);

  /** The data traction of boundary @p id at @p x with outward normal
   * @p normal: Loads/Tractions and Projected pressures (2D and 3D face
   * tractions alike). */
  template <int dim>
  dealii::Tensor<1, dim>
  data_traction(const Scene<dim>                &scene,
                const dealii::types::boundary_id id,
                const dealii::Point<dim>        &x,
                const dealii::Tensor<1, dim>    &normal);

  /**
   * The pseudo-inverses of the vertex problems' +-1 matrices (a face's
   * owner +1, its other side -1), kept per sign pattern: most vertices of a
   * mesh share one of a few. The key is n, m and the n x m entries row by
   * row.
   */
  class VertexProblemInverses
  {
  public:
    const dealii::FullMatrix<double> &
    operator()(const std::vector<signed char> &key);

  private:
    std::map<std::vector<signed char>, dealii::FullMatrix<double>> inverses;
  };
} // namespace hrcontact

#endif
