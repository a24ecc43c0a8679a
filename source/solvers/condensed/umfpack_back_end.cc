#include <deal.II/base/timer.h>

#include <deal.II/lac/sparse_direct.h>

#include <hrcontact/core/input.h>
#include <hrcontact/solvers/condensed/umfpack_back_end.h>

namespace hrcontact
{
  using namespace dealii;

  struct UmfpackBackEnd::DirectFactor
  {
    /** StepRows::key of the rows it was factorised for. */
    std::vector<double> key;
    SparseDirectUMFPACK factor;
  };

  UmfpackBackEnd::UmfpackBackEnd(const EquilibriumSystem &system,
                                 LinearSolverStatistics  &statistics)
    : system(system)
    , statistics(statistics)
  {}

  UmfpackBackEnd::~UmfpackBackEnd() = default;

  void
  UmfpackBackEnd::assemble(
    const std::function<void(DynamicSparsityPattern &)>  &couplings,
    const std::function<void(const CellStiffnessSink &)> &cells)
  {
    const unsigned int n_u = system.n_displacement_dofs;
    {
      DynamicSparsityPattern dsp(n_u, n_u);
      couplings(dsp);
      sparsity.copy_from(dsp);
    }
    K.reinit(sparsity);
    cells([&](const unsigned int,
              const std::vector<types::global_dof_index> &du,
              const FullMatrix<double> &K_cell) { K.add(du, K_cell); });
  }

  void
  UmfpackBackEnd::rows_changed()
  {
    direct_factor.reset();
  }

  void
  UmfpackBackEnd::flexibility_changed()
  {
    direct_factor.reset();
  }

  void
  UmfpackBackEnd::factorise(const StepRows &rows)
  {
    direct_factor.reset(); // free the old factors first
    direct_factor      = std::make_unique<DirectFactor>();
    direct_factor->key = rows.key;
    SparseMatrix<double> A(sparsity);
    A.copy_from(K);
    FullMatrix<double> spring_matrix;
    Vector<double>     spring_force;
    for (const Spring &spring : rows.springs)
      {
        spring.matrix_and_force(spring_matrix, spring_force);
        const auto &dofs = spring.row->combination;
        for (unsigned int a = 0; a < dofs.size(); ++a)
          for (unsigned int b = 0; b < dofs.size(); ++b)
            A.add(dofs[a].first, dofs[b].first, spring_matrix(a, b));
      }
    rows.constraints.condense(A);
    try
      {
        direct_factor->factor.initialize(A);
      }
    catch (const std::exception &)
      {
        direct_factor.reset();
        throw SingularStiffnessError(singular_stiffness_message);
      }
    ++statistics.preconditioner_setups;
  }

  void
  UmfpackBackEnd::solve(const StepRows    &rows,
                        const StrainLoads &loads,
                        FieldVector       &u)
  {
    // K and the springs, factorised again only when a held row or a
    // spring's compliance changed (DirectFactor).
    const unsigned int n_u = system.n_displacement_dofs;
    Timer              timer;
    double             factor_seconds = 0;
    if (!direct_factor || direct_factor->key != rows.key)
      {
        factorise(rows);
        factor_seconds = timer.wall_time();
        statistics.setup_seconds += factor_seconds;
      }
    const auto &constraints = rows.constraints;
    // u = u_c + v: u_c carries the inhomogeneities (the held values),
    // v solves the homogeneously constrained system with the right-hand
    // side f + spring forces - (K + springs) u_c, condensed like the
    // matrix.
    Vector<double> u_c(n_u), r(n_u);
    constraints.distribute(u_c);
    K.residual(r, u_c, Vector<double>(system.load.begin(), system.load.end()));
    loads.for_each([&](const std::vector<types::global_dof_index> &dofs,
                       const Vector<double>                       &values) {
      for (unsigned int i = 0; i < dofs.size(); ++i)
        r[dofs[i]] += values[i];
    });
    FullMatrix<double> spring_matrix;
    Vector<double>     spring_force;
    for (const Spring &spring : rows.springs)
      {
        spring.matrix_and_force(spring_matrix, spring_force);
        const auto &dofs = spring.row->combination;
        for (unsigned int a = 0; a < dofs.size(); ++a)
          {
            double spring_times_u_c = 0;
            for (unsigned int b = 0; b < dofs.size(); ++b)
              spring_times_u_c += spring_matrix(a, b) * u_c[dofs[b].first];
            r[dofs[a].first] += spring_force[a] - spring_times_u_c;
          }
      }
    for (const auto &line : constraints.get_lines())
      for (const auto &[dof, coefficient] : line.entries)
        r[dof] += coefficient * r[line.index];
    for (const auto &line : constraints.get_lines())
      r[line.index] = 0;
    Vector<double> x(n_u);
    direct_factor->factor.vmult(x, r);
    constraints.distribute(x);
    u.reinit(n_u);
    std::copy(x.begin(), x.end(), u.begin());
    statistics.solve_seconds += timer.wall_time() - factor_seconds;
  }
} // namespace hrcontact
