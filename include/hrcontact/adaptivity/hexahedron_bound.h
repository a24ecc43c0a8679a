#ifndef hrcontact_hexahedron_bound_h
#define hrcontact_hexahedron_bound_h

#include <deal.II/base/function.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/results.h>

#include <array>
#include <string>
#include <vector>

namespace hrcontact
{
  class HexahedronFaceTractions;
  class HexahedronEquilibration;

  /**
   * The error bound in 3D (EquilibratedStress's two steps on a conforming
   * mesh of parallelepipeds, linear elastic bodies): HexahedronFaceTractions
   * balance every cell, HexahedronEquilibration finds in each the
   * admissible stress nearest C eps(u_h). On a parallelepiped the Q1 map is
   * affine and u_h, sigma_h are trilinear in the cell's own coordinates, so
   * they are sampled from their vertex values in closed form.
   */
  class HexahedronBound
  {
  public:
    explicit HexahedronBound(const Results<3> &results);

    /** What the 3D bound does not cover in @p results (empty if nothing):
     * cells that are not parallelepipeds, hanging nodes, contact rows,
     * nonlinear laws, elements whose shape functions are not in Q1. */
    static std::string
    not_covered(const Results<3> &results);

    /** Per own cell: tau's coefficients, eta_K^2 and |sigma_h|^2_{C^-1,K};
     * the admissibility residuals. */
    void
    compute(std::vector<dealii::Vector<double>> &coefficients,
            std::vector<double>                 &bound_squared,
            double                              &solution_energy,
            double                              &traction_residual,
            double                              &cell_residual) const;

    /** Against an exact stress: |sigma - C eps(u_h)|^2, |sigma - tau|^2,
     * |sigma - sigma_h|^2 and |sigma|^2 (this process's cells). */
    std::array<double, 4>
    compare(const std::vector<dealii::Vector<double>> &coefficients,
            const dealii::Function<3>                 &reference) const;

  private:
    const Results<3> &results;
    /** u_h and sigma_h at a point of the current cell, from their vertex
     * values. */
    struct CellFields
    {
      dealii::Point<3>                             v0;
      dealii::Tensor<2, 3>                         J_inv;
      std::array<dealii::Tensor<1, 3>, 8>          u;
      std::array<dealii::SymmetricTensor<2, 3>, 8> s;
      dealii::SymmetricTensor<2, 3>
      strain(const dealii::Point<3> &x) const;
      dealii::SymmetricTensor<2, 3>
      stress(const dealii::Point<3> &x) const;
    };
    void
    sample(const dealii::DoFHandler<3>::active_cell_iterator &cell,
           CellFields                                        &fields) const;
    using Cell = dealii::DoFHandler<3>::active_cell_iterator;
    /** A batch of cells of one body: their data, one solve, their shares
     * of the bound and of the stresses' energy. */
    void
    solve_batch(const HexahedronFaceTractions       &faces,
                const double                         sigma_max,
                HexahedronEquilibration             &eq,
                const std::vector<Cell>             &cells,
                std::vector<dealii::Vector<double>> &coefficients,
                std::vector<double>                 &bound_squared,
                double                              &solution_energy,
                double                              &cell_residual) const;
  };
} // namespace hrcontact

#endif
