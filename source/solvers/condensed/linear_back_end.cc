#include <hrcontact/solvers/condensed/linear_back_end.h>
#include <hrcontact/solvers/condensed/trilinos_cg_amg.h>
#include <hrcontact/solvers/condensed/trilinos_mumps.h>
#include <hrcontact/solvers/condensed/umfpack_back_end.h>

namespace hrcontact
{
  const std::string singular_stiffness_message =
    "Condensed path: the stiffness B F^-1 B^T with the current supports is "
    "singular: the body has a zero-energy mode (a mechanism, an unsupported "
    "body, or a stress space too poor for the mesh). The null-space path "
    "(Equilibrium reduction/Path = null-space) names the nodes the mode "
    "moves.";

  void
  CondensedBackEnd::set_start(const FieldVector &)
  {}

  bool
  CondensedBackEnd::tighten()
  {
    return false;
  }

  std::unique_ptr<CondensedBackEnd>
  create_condensed_back_end(const LinearSolverKind      solver,
                            const EquilibriumSystem    &system,
                            const LinearSolverSettings &settings,
                            const DofPartition         &partition,
                            const bool                  ghosted_u,
                            LinearSolverStatistics     &statistics)
  {
    if (solver == LinearSolverKind::cg_amg)
      return std::make_unique<TrilinosCgAmg>(
        system, settings, partition, ghosted_u, statistics);
    if (partition.distributed())
      return std::make_unique<TrilinosMumps>(
        system, settings, partition, ghosted_u, statistics);
    return std::make_unique<UmfpackBackEnd>(system, statistics);
  }
} // namespace hrcontact
