#include <deal.II/lac/vector.h>

#include <hrcontact/constraints/curved_obstacle_relinearisation.h>
#include <hrcontact/discretisation/hr_assembler.h>
#include <hrcontact/solvers/newton_step.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  CurvedObstacleRelinearisation<dim>::CurvedObstacleRelinearisation(
    const Scene<dim>  &scene,
    EquilibriumSystem &system)
    : scene(scene)
    , system(system)
  {
    for (unsigned int r = 0; r < system.rows.size(); ++r)
      rows_of_node[system.rows[r].node].push_back(r);
  }

  template <int dim>
  bool
  CurvedObstacleRelinearisation<dim>::relinearise(
    NewtonStepPath            &path,
    const std::vector<double> &opening)
  {
    // The tangent obstacle at the point of the surface nearest to the
    // current position X + u of each node (the straight case of eq. 10 at
    // the current configuration): new normal n, gap g = (x_surface - X).n,
    // with the prescribed components of the node taken out as the assembler
    // does; the node's free rows complete the basis again.
    std::vector<double> w(opening.size());
    for (unsigned int k = 0; k < w.size(); ++k)
      w[k] = system.rows[system.contact_rows[k]].value + opening[k];
    Vector<double> u;
    path.displacements(w, u);
    const double u_max   = u.linfty_norm();
    bool         changed = false;
    for (const unsigned int r : system.contact_rows)
      {
        EquilibriumRow &row = system.rows[r];
        const auto      co  = scene.curved_obstacles.find(row.obstacle);
        // Corner nodes (several obstacles) stay linearised at the start.
        if (row.obstacle < 0 || co == scene.curved_obstacles.end() ||
            !row.direction.empty())
          continue;
        Point<dim> X, x;
        for (unsigned int d = 0; d < dim; ++d)
          {
            X[d] = system.node_coordinates[row.node][d];
            x[d] = X[d] + u[row.combination[d].first];
          }
        const auto [surface, n]            = co->second.project(x);
        Tensor<1, dim>              n_free = n;
        double                      g      = (surface - X) * n;
        std::vector<Tensor<1, dim>> taken;
        for (const unsigned int s : rows_of_node[row.node])
          if (system.rows[s].row_class == RowClass::prescribed)
            for (unsigned int d = 0; d < dim; ++d)
              if (system.rows[s].combination[d].second == 1.)
                {
                  g -= n[d] * system.rows[s].value;
                  n_free[d] = 0;
                  Tensor<1, dim> e;
                  e[d] = 1;
                  taken.push_back(e);
                }
        const double length = n_free.norm();
        if (length < 1e-8)
          continue;
        n_free /= length;
        g /= length;
        // Changed: beyond 1e-8 of the displacements (the finite-difference
        // gradient of a level set is good to about that).
        double turn = 0;
        for (unsigned int d = 0; d < dim; ++d)
          turn += std::abs(n_free[d] - row.combination[d].second);
        if (std::abs(g - row.value) + turn * u_max >
            1e-8 * (u_max + std::abs(g)))
          changed = true;
        for (unsigned int d = 0; d < dim; ++d)
          row.combination[d].second = n_free[d];
        row.value = g;
        taken.push_back(n_free);
        // The free rows: the orthogonal complement, as the assembler has it.
        const auto   complement = orthogonal_complement<dim>(taken);
        unsigned int next       = 0;
        for (const unsigned int s : rows_of_node[row.node])
          if (system.rows[s].row_class == RowClass::free &&
              next < complement.size())
            {
              for (unsigned int d = 0; d < dim; ++d)
                system.rows[s].combination[d].second = complement[next][d];
              ++next;
            }
      }
    if (changed)
      path.rows_changed();
    return changed;
  }

  template class CurvedObstacleRelinearisation<2>;
  template class CurvedObstacleRelinearisation<3>;
} // namespace hrcontact
