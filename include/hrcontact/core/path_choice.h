#ifndef hrcontact_path_choice_h
#define hrcontact_path_choice_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace hrcontact
{
  /**
   * The Newton-step path a run takes (doc/method.md, "Two exact Newton-step
   * paths"): the paper's dense null-space reduction (eq. 40-47) or the
   * condensed sparse system. Identical iterates in exact arithmetic.
   */
  enum class SolutionPath
  {
    null_space,
    condensed
  };

  /** "null-space" or "condensed", as summary.txt writes it. */
  std::string
  to_string(const SolutionPath path);

  std::ostream &
  operator<<(std::ostream &out, const SolutionPath path);

  /** What a scene asks of the path, besides its size. */
  struct PathNeeds
  {
    /** Augmented Lagrangian/Regularisation = displacement AL: condensed. */
    bool displacement_al = false;
    /** Rows that follow the configuration (curved obstacles): condensed. */
    bool relinearise = false;
    /** A distributed mesh: no process holds the dense reduction. */
    bool distributed_mesh = false;
    /** A nonlinear law or a stress constraint: automatic takes condensed
     * (dozens of Newton steps, each a dense solve on the null-space path). */
    bool material_iteration = false;
    /** A locally refined mesh: its hanging nodes are constraints of the
     * displacement solve, which the null-space reduction does not have. */
    bool hanging_nodes = false;
  };

  /**
   * Equilibrium reduction/Path and Automatic dense limit, parsed once into
   * an enum, and the policy that turns them and the size of the dense
   * reduction into a SolutionPath.
   */
  class PathChoice
  {
  public:
    enum class Setting
    {
      automatic,
      null_space,
      condensed
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Bytes of the dense null-space reduction: C (n x tau), the null-space
     * basis (n x m) and M0 with its factor, m = tau - n. */
    static double
    dense_reduction_bytes(const double n_free_rows,
                          const double n_stress_unknowns);

    /** Whether dense matrices of this many bytes are within Automatic dense
     * limit. */
    bool
    dense_fits(const double bytes) const;

    /**
     * Whether the dense reduction fits with every displacement dof a free
     * row. Its bytes fall as the free rows grow, so this bounds those of
     * any classification from below: where it does not fit, the path is
     * condensed whatever the rows.
     */
    bool
    dense_fits_every_dof_free(const double n_displacement_dofs,
                              const double n_stress_unknowns) const;

    /** The path for a system whose dense reduction takes dense_bytes; logs
     * it, and refuses a forced null-space path that cannot serve. */
    SolutionPath
    choose(const double     dense_bytes,
           const PathNeeds &needs,
           std::ostream    &log) const;

    Setting setting               = Setting::automatic;
    double  automatic_dense_limit = 2e9;
  };
} // namespace hrcontact

#endif
