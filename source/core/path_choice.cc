#include <hrcontact/core/input.h>
#include <hrcontact/core/path_choice.h>

#include <algorithm>
#include <iomanip>

namespace hrcontact
{
  using namespace dealii;

  std::string
  to_string(const SolutionPath path)
  {
    return path == SolutionPath::null_space ? "null-space" : "condensed";
  }

  std::ostream &
  operator<<(std::ostream &out, const SolutionPath path)
  {
    return out << to_string(path);
  }

  void
  PathChoice::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Equilibrium reduction");
    prm.declare_entry(
      "Path",
      "automatic",
      Patterns::Selection("automatic|null-space|condensed"),
      "How every Newton step (and the linear solve without contact) is "
      "computed, with identical results in exact arithmetic: null-space is "
      "the paper's dense reduction to the self-equilibrated stresses s0 "
      "(names the nodes of a mechanism; memory ~ 8 (tau n + n m + 2 m^2) "
      "bytes); condensed eliminates the stresses cell by cell and solves the "
      "sparse system B F^-1 B^T with UMFPACK (grows about linearly); "
      "automatic takes null-space while its dense matrices fit in Automatic "
      "dense limit, and condensed for a nonlinear material or a stress "
      "constraint (whose material iteration solves dozens of Newton steps: "
      "a masonry arch took 7 min 51 s on the dense path, 2.3 s condensed).");
    prm.declare_entry("Automatic dense limit",
                      "2e9",
                      Patterns::Double(0),
                      "Bytes of dense matrices up to which Path = automatic "
                      "takes the null-space path.");
    prm.leave_subsection();
  }

  void
  PathChoice::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Equilibrium reduction");
    setting               = get_selection<Setting>(prm,
                                     "Path",
                                     {{"automatic", Setting::automatic},
                                                    {"null-space", Setting::null_space},
                                                    {"condensed", Setting::condensed}});
    automatic_dense_limit = prm.get_double("Automatic dense limit");
    prm.leave_subsection();
  }

  double
  PathChoice::dense_reduction_bytes(const double n_free_rows,
                                    const double n_stress_unknowns)
  {
    const double n = n_free_rows, tau = n_stress_unknowns;
    const double m = std::max(0., tau - n);
    return 8 * (tau * n + n * m + 2 * m * m);
  }

  bool
  PathChoice::dense_fits(const double bytes) const
  {
    return bytes <= automatic_dense_limit;
  }

  bool
  PathChoice::dense_fits_every_dof_free(const double n_displacement_dofs,
                                        const double n_stress_unknowns) const
  {
    return dense_fits(
      dense_reduction_bytes(n_displacement_dofs, n_stress_unknowns));
  }

  SolutionPath
  PathChoice::choose(const double     dense_bytes,
                     const PathNeeds &needs,
                     std::ostream    &log) const
  {
    if (needs.displacement_al && setting == Setting::null_space)
      throw InputError(
        "Augmented Lagrangian/Regularisation = displacement augmented "
        "Lagrangian needs Equilibrium reduction/Path = condensed (or "
        "automatic): the null-space path cannot leave a contact node free of "
        "both a spring and a support.");
    if (needs.relinearise && setting == Setting::null_space)
      throw InputError(
        "Contact/Update curved obstacles = true needs Equilibrium "
        "reduction/Path = condensed (or automatic): the null-space "
        "reduction is built once from the initial constraint directions.");
    if (needs.hanging_nodes && setting == Setting::null_space)
      throw InputError(
        "Mesh refinement: a locally refined mesh (hanging nodes) needs "
        "Equilibrium reduction/Path = condensed (or automatic): the "
        "null-space reduction has no hanging-node constraints.");
    const bool forced_condensed = needs.displacement_al || needs.relinearise ||
                                  needs.distributed_mesh || needs.hanging_nodes;
    // Automatic: the paper's dense reduction while it fits, but not for a
    // material iteration.
    std::string  why;
    SolutionPath path = SolutionPath::condensed;
    if (!forced_condensed && setting == Setting::null_space)
      path = SolutionPath::null_space;
    if (!forced_condensed && setting == Setting::automatic)
      {
        if (dense_fits(dense_bytes) && needs.material_iteration)
          why = "for the material iteration; ";
        if (dense_fits(dense_bytes) && why.empty())
          path = SolutionPath::null_space;
      }
    log << "  Newton-step path: " << path << " (" << why
        << "dense reduction would need about " << std::setprecision(3)
        << dense_bytes / 1e9 << " GB)" << std::endl;
    return path;
  }
} // namespace hrcontact
