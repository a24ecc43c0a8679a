#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <hrcontact/adaptivity/support_mismatch.h>

#include <cmath>

namespace hrcontact
{
  using namespace dealii;

  template <int dim>
  double
  support_mismatch(const Results<dim> &results)
  {
    const QGauss<dim - 1>       rule(3);
    FEFaceValues<dim>           fv(StaticMappingQ1<dim>::mapping,
                         *results.spaces.fe_displacement,
                         rule,
                         update_values | update_quadrature_points |
                           update_normal_vectors);
    std::vector<Vector<double>> u(rule.size(), Vector<double>(dim));
    double                      mismatch = 0;
    for (const auto &cell :
         results.spaces.dof_handler_displacement.active_cell_iterators())
      if (results.partition.owned_cell[cell->active_cell_index()])
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const types::boundary_id id   = cell->face(f)->boundary_id();
              bool                     held = false;
              for (const auto &source : results.scene.constraints)
                held = held || source->acts_on(id);
              if (!held)
                continue;
              fv.reinit(cell, f);
              fv.get_function_values(results.displacement, u);
              for (const auto &source : results.scene.constraints)
                if (source->acts_on(id))
                  for (unsigned int q = 0; q < rule.size(); ++q)
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        const double value =
                          source->prescribed_value(id,
                                                   d,
                                                   fv.quadrature_point(q));
                        if (std::isfinite(value))
                          mismatch =
                            std::max(mismatch, std::abs(u[q][d] - value));
                      }
              // A bilateral normal constraint u . n = g.
              for (const auto &source : results.scene.constraints)
                if (source->acts_on(id))
                  for (unsigned int q = 0; q < rule.size(); ++q)
                    {
                      const double g =
                        source->normal_value(id, fv.quadrature_point(q));
                      double u_n = 0;
                      for (unsigned int d = 0; d < dim; ++d)
                        u_n += u[q][d] * fv.normal_vector(q)[d];
                      if (std::isfinite(g))
                        mismatch = std::max(mismatch, std::abs(u_n - g));
                    }
            }
    const MPI_Comm comm  = results.partition.communicator;
    mismatch             = Utilities::MPI::max(mismatch, comm);
    const double largest = results.displacement.linfty_norm();
    return largest > 0 ? mismatch / largest : mismatch;
  }

  template double
  support_mismatch(const Results<2> &);
  template double
  support_mismatch(const Results<3> &);
} // namespace hrcontact
