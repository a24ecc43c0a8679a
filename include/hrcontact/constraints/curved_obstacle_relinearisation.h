#ifndef hrcontact_curved_obstacle_relinearisation_h
#define hrcontact_curved_obstacle_relinearisation_h

#include <hrcontact/core/scene.h>
#include <hrcontact/discretisation/equilibrium_system.h>
#include <hrcontact/solvers/row_relinearisation.h>

#include <map>
#include <vector>

namespace hrcontact
{
  /**
   * Contact/Update curved obstacles: the Q rows of the curved obstacles,
   * linearised again at the current configuration between multiplier
   * updates. Each row becomes the straight obstacle tangent at the point of
   * the surface nearest to the node's current position X + u (the straight
   * case of eq. 10 at the current configuration): new normal n, gap g =
   * (x_surface - X) . n, with the node's prescribed components taken out as
   * at the start; the node's free rows complete the basis again. Corner
   * nodes (several obstacles) stay linearised at the start.
   */
  template <int dim>
  class CurvedObstacleRelinearisation : public RowRelinearisation
  {
  public:
    /** The rows of `system` it updates; both must outlive it. */
    CurvedObstacleRelinearisation(const Scene<dim>  &scene,
                                  EquilibriumSystem &system);

    bool
    relinearise(NewtonStepPath            &path,
                const std::vector<double> &opening) override;

  private:
    const Scene<dim>                                 &scene;
    EquilibriumSystem                                &system;
    std::map<unsigned int, std::vector<unsigned int>> rows_of_node;
  };
} // namespace hrcontact

#endif
