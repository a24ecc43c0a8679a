#ifndef hrcontact_section_forces_h
#define hrcontact_section_forces_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/discretisation/field_vector.h>
#include <hrcontact/discretisation/mixed_spaces.h>
#include <hrcontact/geometry/tunnel_lining.h>

#include <vector>

namespace hrcontact
{
  /**
   * Stress resultants on one section: N, V, M act on the part of the bar
   * before the section (smaller s) at its cut face, whose outward normal is
   * the mid-line tangent tau = (across_y, -across_x). N = int sigma_tt (tension
   * positive), V = int sigma_tn (along `across`), M = -int (xi - xi_c)
   * sigma_tt with xi the coordinate along `across` and xi_c the centre of the
   * section: positive M stretches the inner fibre (sagging for a beam whose
   * `across` points up).
   */
  struct SectionForce
  {
    SectionStation       station;
    dealii::Point<2>     inner, outer, centre;
    double               thickness = 0;
    double               N = 0, V = 0, M = 0;
    double               sigma_inner = 0, sigma_outer = 0; // sigma_tt at faces
    dealii::Tensor<1, 2> displacement;                     // at the centre
  };

  /**
   * Integrates the discrete stress field across sections of a 2D body. The
   * line through each station is clipped against every cell (cells are
   * convex, edges straight under the Q1 mapping); the connected piece that
   * contains the station is the section, and each cell's part of it is
   * integrated with 4 Gauss points, so the discontinuity of the stresses
   * between cells is respected. Pieces shared by two cells (a section along
   * a mesh line) are counted once. 3D bodies are refused.
   */
  template <int dim>
  std::vector<SectionForce>
  compute_section_forces(const MixedSpaces<dim>            &spaces,
                         const FieldVector                 &stress,
                         const FieldVector                 &displacement,
                         const std::vector<SectionStation> &stations);

  /**
   * Extremes of the in-plane principal stresses over the cell vertices of
   * the discontinuous field (what a nodal contour plot shows): {min, max} of
   * sigma_min, then {min, max} of sigma_max. Cells whose centre lies within
   * `exclude_radius` of `exclude_centre` are skipped (a corner singularity
   * whose peak grows without bound under refinement). 2D only.
   */
  template <int dim>
  std::array<double, 4>
  principal_stress_extremes(const MixedSpaces<dim>   &spaces,
                            const FieldVector        &stress,
                            const dealii::Point<dim> &exclude_centre = {},
                            const double              exclude_radius = 0);
} // namespace hrcontact

#endif
