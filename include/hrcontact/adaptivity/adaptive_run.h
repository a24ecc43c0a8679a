#ifndef hrcontact_adaptive_run_h
#define hrcontact_adaptive_run_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hrcontact/adaptivity/adaptive_refinement.h>
#include <hrcontact/postprocess/summary.h>

#include <ostream>

namespace hrcontact
{
  /**
   * A run with `Mesh refinement/Adaptive cycles` > 0: solve the scene, let
   * the Estimator rate each cell, mark the fractions, and solve the scene
   * again on the mesh refined so (each cycle an HRProblem of its own, its
   * mesh the scene's with the steps so far replayed), until the cycles or
   * `Maximum dofs` are used up. The last cycle writes the results, with
   * every cycle's line in summary.txt. A progress line per cycle. Returns
   * the steps and the cycles' records; @p summary, if given, gets the last
   * cycle's summary.txt (tests).
   */
  template <int dim>
  AdaptiveRefinement<dim>
  run_adaptive_cycles(dealii::ParameterHandler &prm,
                      std::ostream             &log,
                      const MPI_Comm            communicator = MPI_COMM_WORLD,
                      Summary                  *summary      = nullptr);
} // namespace hrcontact

#endif
