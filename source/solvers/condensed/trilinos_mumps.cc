#include <deal.II/base/timer.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/trilinos_mumps.h>

#include <Amesos.h>

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
    try
      {
        // The symbolic analysis (ordering, elimination tree) depends on
        // the pattern only, which TrilinosBackEnd keeps for the back end's
        // life: it is done once; every new matrix is factorised
        // numerically on it (the no-tension pier at 790k dofs: each
        // material step's factorisation 4.2 s with the analysis).
        if (!solver)
          {
            problem = std::make_unique<Epetra_LinearProblem>();
            problem->SetOperator(
              const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
            Amesos factory;
            solver.reset(factory.Create("Amesos_Mumps", *problem));
            AssertThrow(solver, ExcMessage("Amesos has no MUMPS"));
            if (solver->SymbolicFactorization() != 0)
              throw InputError(singular_stiffness_message);
          }
        if (!factorised)
          {
            if (solver->NumericFactorization() != 0)
              throw InputError(singular_stiffness_message);
            factorised = true;
            ++statistics.preconditioner_setups;
            factor_seconds = timer.wall_time();
            statistics.setup_seconds += factor_seconds;
          }
        problem->SetLHS(&x.trilinos_vector());
        problem->SetRHS(const_cast<Epetra_MultiVector *>(
          static_cast<const Epetra_MultiVector *>(&rhs.trilinos_vector())));
        if (solver->Solve() != 0)
          throw InputError(singular_stiffness_message);
      }
    catch (const InputError &)
      {
        solver.reset();
        throw;
      }
    catch (const std::exception &)
      {
        solver.reset();
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
