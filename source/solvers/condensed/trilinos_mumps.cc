#include <deal.II/base/timer.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/trilinos_mumps.h>

namespace hrcontact
{
  using namespace dealii;

  void
  TrilinosMumps::matrix_changing()
  {
    direct_solver.reset();
  }

  void
  TrilinosMumps::drop_matrix_dependents()
  {
    direct_solver.reset();
  }

  void
  TrilinosMumps::solve_assembled()
  {
    Timer  timer;
    double factor_seconds = 0;
    try
      {
        if (!direct_solver)
          {
            direct_control = std::make_unique<SolverControl>(1, 0);
            direct_solver  = std::make_unique<TrilinosWrappers::SolverDirect>(
              *direct_control,
              TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                             "Amesos_Mumps"));
            direct_solver->initialize(matrix);
            ++statistics.preconditioner_setups;
            factor_seconds = timer.wall_time();
            statistics.setup_seconds += factor_seconds;
          }
        direct_solver->solve(x, rhs);
      }
    catch (const std::exception &)
      {
        direct_solver.reset();
        throw InputError(singular_stiffness_message);
      }
    // MUMPS returns some vector for a singular matrix (a floating body, a
    // mechanism) without a word: an inconsistent system shows in the
    // residual, which UMFPACK and CG would have refused.
    TrilinosWrappers::MPI::Vector residual(rhs);
    matrix.vmult(residual, x);
    residual -= rhs;
    const double scale = rhs.l2_norm();
    if (!(residual.l2_norm() <= 1e-8 * std::max(scale, 1e-300)))
      throw InputError(singular_stiffness_message);
    statistics.solve_seconds += timer.wall_time() - factor_seconds;
  }
} // namespace hrcontact
