#include <deal.II/base/timer.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/trilinos_mumps.h>

#include <string>

namespace hrcontact
{
  using namespace dealii;

  void
  TrilinosMumps::matrix_changing()
  {
    factorised = false;
  }

  void
  TrilinosMumps::drop_matrix_dependents()
  {
    factorised = false;
  }

  void
  TrilinosMumps::solve_assembled()
  {
    Timer  timer;
    double factor_seconds = 0;
    // The symbolic analysis (ordering, elimination tree) depends on the
    // pattern only, which TrilinosBackEnd keeps for the back end's life: it
    // is done once; every new matrix is factorised numerically on it.
    if (!factor)
      factor = std::make_unique<MumpsFactor>(partition.communicator);
    // -10: numerically singular (a floating body or a mechanism); anything
    // else is MUMPS' own failure, named by its code.
    const auto fail = [&]() {
      const int code = factor->error();
      factor.reset();
      if (code == -10)
        throw SingularStiffnessError(singular_stiffness_message);
      throw InputError(
        "Linear solver: MUMPS failed with INFOG(1) = " + std::to_string(code) +
        " (its user guide names the cause); Solver = cg-amg "
        "avoids it.");
    };
    if (!factorised)
      {
        if (!factor->factorise(matrix.trilinos_matrix()))
          fail();
        factorised = true;
        ++statistics.preconditioner_setups;
        factor_seconds = timer.wall_time();
        statistics.setup_seconds += factor_seconds;
      }
    if (!factor->solve(rhs.trilinos_vector(), x.trilinos_vector()))
      fail();
    // MUMPS returns some vector for a singular matrix (a floating body, a
    // mechanism) without a word: an inconsistent system shows in the
    // residual, which UMFPACK and CG would have refused.
    TrilinosWrappers::MPI::Vector residual(rhs);
    matrix.vmult(residual, x);
    residual -= rhs;
    const double scale = rhs.l2_norm();
    if (!(residual.l2_norm() <= 1e-8 * std::max(scale, 1e-300)))
      throw SingularStiffnessError(singular_stiffness_message);
    statistics.solve_seconds += timer.wall_time() - factor_seconds;
  }
} // namespace hrcontact
