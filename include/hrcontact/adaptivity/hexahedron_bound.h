#ifndef hrcontact_hexahedron_bound_h
#define hrcontact_hexahedron_bound_h

#include <deal.II/base/function.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/results.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hrcontact
{
  class HexahedronShapeMap;

  /**
   * The error bound in 3D (EquilibratedStress's two steps on a conforming
   * mesh of parallelepipeds, linear elastic bodies): HexahedronFaceTractions
   * balance every cell, HexahedronEquilibration finds in each the
   * admissible stress nearest C eps(u_h). That cell problem is linear in
   * the cell's data (u_h at the vertices, the face tractions, the body
   * force) and its factors depend on the shape only, so per shape it is
   * solved once for each of the 144 data (HexahedronShapeMap) and a cell
   * costs a few small products. On a parallelepiped the Q1 map is affine
   * and u_h, sigma_h are trilinear in the cell's own coordinates, so they
   * are sampled from their vertex values in closed form.
   */
  class HexahedronBound
  {
  public:
    explicit HexahedronBound(const Results<3> &results);
    ~HexahedronBound();

    /** What the 3D bound does not cover in @p results (empty if nothing):
     * cells that are not parallelepipeds, hanging nodes, contact rows,
     * nonlinear laws, elements whose shape functions are not in Q1. */
    static std::string
    not_covered(const Results<3> &results);

    /** Per active cell eta_K^2 (own cells), |sigma_h|^2_{C^-1} summed
     * over the processes; the admissibility residuals. */
    void
    compute(std::vector<double> &bound_squared,
            double              &solution_energy,
            double              &traction_residual,
            double              &cell_residual);

    /** Against an exact stress: |sigma - C eps(u_h)|^2, |sigma - tau|^2,
     * |sigma - sigma_h|^2 and |sigma|^2 (this process's cells), tau from
     * the data compute() kept. */
    std::array<double, 4>
    compare(const dealii::Function<3> &reference) const;

  private:
    const Results<3> &results;
    /** u_h and sigma_h at the vertices of a cell. */
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
    /** The finite elements' shape values at the unit cell's vertices. */
    std::vector<std::array<double, 8>> u_at_vertices, s_at_vertices;
    void
    sample(const dealii::DoFHandler<3>::active_cell_iterator &cell,
           CellFields                                        &fields) const;
    /** Per body its cell problem and the maps of its shapes; per own cell
     * its map, its size over the map's and its data. */
    struct Body;
    std::map<dealii::types::material_id, std::unique_ptr<Body>> bodies;
    struct CellMap
    {
      const HexahedronShapeMap *map = nullptr;
      double                    s   = 1;
      std::vector<double>       d;
    };
    std::vector<CellMap> cell_maps;
  };
} // namespace hrcontact

#endif
