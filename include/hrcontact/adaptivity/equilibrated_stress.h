#ifndef hrcontact_equilibrated_stress_h
#define hrcontact_equilibrated_stress_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/results.h>

#include <array>
#include <memory>
#include <vector>

namespace hrcontact
{
  class FaceTractions;
  class HexahedronBound;

  /**
   * A statically admissible stress tau reconstructed from the HR stresses:
   * symmetric, div tau + f = 0 and tau n continuous across every face
   * exactly (to round-off), tau n = t on the loaded boundary. With the
   * displacement u_h (conforming Q1, the supports held) it gives the
   * Prager-Synge (hypercircle) identity
   *
   *   |u - u_h|_E^2 + |sigma - tau|_{C^-1}^2 = |tau - C eps(u_h)|_{C^-1}^2,
   *
   * so that eta = |tau - C eps(u_h)|_{C^-1} bounds the energy error of u_h
   * with no constant (doc/error-bounds.md). We write this construction
   * ourselves: deal.II has no symmetric equilibrated stress element.
   *
   * Two local steps (Ladevèze's element equilibration): FaceTractions
   * balance every cell, then CellEquilibration finds in each cell a
   * symmetric piecewise-polynomial stress with those tractions.
   *
   * Exact for body forces of degree < CellEquilibration::degree and
   * tractions of degree <= CellEquilibration::degree on each face; other
   * data are projected. So far: 2D (with hanging nodes), linear
   * elastic bodies and nonlinear laws that give their complementary
   * potential (Ramberg-Osgood: eta^2 is then twice the Fenchel-Young gap
   * int phi^c(tau) + W(eps(u_h)) - tau : eps(u_h), CellEquilibration), supports
   * by prescribed displacements and point supports, unilateral contact with
   * straight obstacles (ContactTractions: the contact faces' tractions, the
   * contact term, the lift of a penetrating u_h); other scenes are refused by
   * name.
   */
  template <int dim>
  class EquilibratedStress
  {
  public:
    /** Refuses (InputError) what the construction does not cover. */
    explicit EquilibratedStress(const Results<dim> &results);

    /** What can be refused before the solve: 3D, contact, nonlinear or
     * cone-constrained bodies (InputError naming it). */
    static void
    check_scene(const Scene<dim> &scene);

    /** What the classified rows show before the solve: contact rows the
     * construction does not carry (ContactRowKinds::not_covered),
     * prescribed rows along no axis (InputError naming it). */
    static void
    check_rows(const EquilibriumSystem &system);

    /** Both steps. */
    void
    compute();

    /** |tau - C eps(u_h)|^2_{C^-1} per active cell: eta^2 is their sum. */
    const std::vector<double> &
    cell_bound_squared() const
    {
      return bound_squared;
    }

    /** eta. */
    double
    bound() const;

    /** |sigma_h|^2_{C^-1}: the energy of the computed stresses. */
    double
    solution_energy_squared() const
    {
      return solution_energy;
    }

    /**
     * How exactly tau is admissible: the largest residual of the vertex
     * problems (force, relative to the largest cell residual of the HR
     * stresses) and of the cells' constraints (equilibrium, face tractions,
     * inner continuity; relative to the largest traction integral).
     */
    double traction_residual = 0, cell_residual = 0;

    /**
     * Contact (ContactTractions): the bound's contact term 2 int (-q) (g -
     * v.d) over Gamma_c (included in cell_bound_squared(), on the faces'
     * cells), the energy norm of the lift w = v - u_h that makes v meet the
     * contact rows where u_h penetrates, and the largest penetration. With
     * a lift, bound() = sqrt((eta_0 + |w|)^2 + contact_term) + |w| (triangle
     * inequality), eta_0^2 the quadratic part.
     */
    double contact_term = 0, lift = 0, largest_penetration = 0;

    /** The energy norms against an exact stress field sigma. */
    struct Comparison
    {
      /** |u - u_h|_E^2 = |sigma - C eps(u_h)|^2_{C^-1}. */
      double displacement_error_squared = 0;
      /** |sigma - tau|^2_{C^-1}. */
      double reconstruction_error_squared = 0;
      /** |sigma - sigma_h|^2_{C^-1}. */
      double stress_error_squared = 0;
      /** |sigma|^2_{C^-1}. */
      double reference_energy_squared = 0;
    };
    Comparison
    compare(const dealii::Function<dim> &reference) const;

  private:
    const Results<dim> &results;
    /** The contact term and the lift, after the cells (2D). */
    void
    add_contact_terms(const FaceTractions &faces);
    /** The polynomial coefficients of each cell's four triangles (2D). */
    std::vector<dealii::Vector<double>> coefficients;
    /** 3D: the cells' data and their shapes' maps (compare()). */
    std::shared_ptr<HexahedronBound> hexahedra;
    std::vector<double>              bound_squared;
    double                           solution_energy = 0;
  };
} // namespace hrcontact

#endif
