#ifndef hrcontact_contact_zone_refinement_h
#define hrcontact_contact_zone_refinement_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/adaptivity/adaptive_refinement.h>
#include <hrcontact/core/results.h>

namespace hrcontact
{
  /**
   * `Mesh refinement/Contact zone depth`: after an adaptive cycle's marks,
   * the cells whose centre lies within `depth` times the pressed zone's size
   * of a pressed contact face are refined up to one level below the finest
   * pressed face.
   *
   * Why: the estimators refine the edge of the contact zone, where the
   * pressure has its square root, and leave the middle of the zone and the
   * body beneath it coarse, where the stresses are smooth and their energy
   * error small. But the peak pressure is set there, by the elastic field
   * over a depth of the zone's size: Hertz with kelly, 4 cycles, 20,714
   * dofs: peak -0.12 % without; -0.04 % with depth 0.5, at 20,898 dofs
   * (doc/adaptivity.md). One level below the finest, because the smooth
   * interior needs less than the edge's square root; the edge keeps the
   * estimator's finest cells.
   *
   * The zone is that of the solved cycle: a boundary face whose every node
   * has a contact row and one of them pressed (ContactFields' status 2);
   * its size the diagonal of the bounding box of the pressed faces' centres.
   * The same cells on every partition (the centres are gathered).
   */
  template <int dim>
  class ContactZoneRefinement
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Add to @p step the cells the rule refines (and keep them from being
     * coarsened); returns how many it added. Collective. */
    unsigned int
    add_to(const Results<dim> &results, RefinementStep &step) const;

    /** 0: off. */
    double depth = 0.5;
  };
} // namespace hrcontact

#endif
