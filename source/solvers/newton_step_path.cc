#include <hrcontact/core/input.h>
#include <hrcontact/solvers/newton_step_path.h>

namespace hrcontact
{
  void
  NewtonStepPath::solve(const std::vector<bool>   &released,
                        const std::vector<double> &mu,
                        const std::vector<double> &alpha,
                        std::vector<double>       &p)
  {
    std::vector<ContactPiece> pieces(released.size());
    for (unsigned int i = 0; i < released.size(); ++i)
      if (released[i])
        {
          pieces[i].spring     = true;
          pieces[i].offset     = mu[i];
          pieces[i].compliance = alpha[i];
        }
    solve(pieces, p);
  }

  void
  NewtonStepPath::set_start(const FieldVector &)
  {}

  void
  NewtonStepPath::rows_changed()
  {}

  bool
  NewtonStepPath::tighten_linear_solver()
  {
    return false;
  }

  void
  NewtonStepPath::contact_displacements(std::vector<double> &) const
  {
    throw InputError(
      "this Newton-step path cannot give the normal displacement of a "
      "contact node without a spring (the displacement-based augmented "
      "Lagrangian needs Equilibrium reduction/Path = condensed).");
  }
} // namespace hrcontact
