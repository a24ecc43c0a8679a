#ifndef hrcontact_material_iteration_h
#define hrcontact_material_iteration_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/discretisation/field_vector.h>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace hrcontact
{
  /**
   * Newton's method on the complementary energy of a nonlinear material
   * (section 2.3: any convex potential phi^c, the algorithm unchanged).
   * Each step replaces phi^c of every cell by its second-order expansion
   * about the last stresses s_k, F_c(s_k) and the strain term d_c = e_c(s_k)
   * - F_c s_k (HRAssembler::refresh_flexibility), and solves the linear
   * mixed problem that leaves: on the condensed path s_c = F_c^{-1} (B_c^T
   * u - d_c) and K u = f + sum B_c F_c^{-1} d_c. Equilibrium holds at every
   * step; the strains of the law become compatible as the steps converge,
   * quadratically near the answer. The first step is the linear solve with
   * the compliance at zero stress.
   *
   * A semismooth term (a stress constraint's projection) can make the full
   * step cycle. With Operations::energy_slope each step is then damped by
   * an exact line search: the energy along s_k + theta delta (delta the
   * full Newton step; both ends in equilibrium, so is the segment) is
   * convex, and its derivative is the cells' slope at theta minus their
   * slope at 0 minus delta^T F_k delta (the Newton step makes the model's
   * derivative vanish at theta = 1), all local: regula falsi finds its
   * zero in (0, 1], theta = 1 when the full step does not overshoot.
   *
   * The iteration stops when the largest change of a stress dof is at most
   * Relative tolerance times the largest stress, or when three changes in a
   * row stay below roundoff_ceiling without falling (the round-off floor of
   * the path, above a tight tolerance: stopped_at_roundoff()); a step that
   * leaves a
   * non-finite stress, or Maximum steps without convergence, ends the run
   * with a NotConvergedError naming the cause.
   */
  class MaterialIteration
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** What one material step does, given by the problem that owns the
     * path and the assembler. */
    struct Operations
    {
      /** One linear solve at the current F_c and d_c. */
      std::function<void()> solve;
      /** The stresses of the last solve (a distributed mesh: the owned
       * and ghost cells'). */
      std::function<void(FieldVector &)> stresses;
      /** F_c and d_c at the given stresses; the path told. */
      std::function<void(const FieldVector &)> linearise_at;
      /**
       * Optional: the derivative of the complementary energy along s0 +
       * theta delta, as HRAssembler::energy_slope gives it, and delta^T
       * F(s0) delta with a non-null last argument. With it, each step is
       * damped by an exact line search (below).
       */
      std::function<
        double(const FieldVector &, const FieldVector &, double, double *)>
        energy_slope;
      /**
       * Optional: the measure of convergence after a step, given the state
       * before and after it; by default the largest change of a state
       * entry relative to the largest entry.
       */
      std::function<double(const FieldVector &, const FieldVector &)> change;
      /**
       * Optional: the state the first solve's linearisation was built at
       * (a continuation: BarrierPath). With it the first step is measured
       * and damped like the others; without it the first step is the
       * elastic one and only starts the iteration.
       */
      const FieldVector *start = nullptr;
    };

    /**
     * Steps until the stresses stop changing. Logs one line per step
     * (its change), throws NotConvergedError as above.
     */
    void
    solve(const Operations &operations, std::ostream &log);

    /** max |s_k - s_{k-1}| / max |s_k| per step after the first. */
    const std::vector<double> &
    change_history() const
    {
      return changes;
    }
    /** The linear solves taken (the first, elastic one included). */
    unsigned int
    n_steps() const
    {
      return steps;
    }

    /** Whether the iteration stopped at the round-off floor of the linear
     * solves rather than at the tolerance. */
    bool
    stopped_at_roundoff() const
    {
      return roundoff_limited;
    }

    /**
     * Whether the last three changes are below `ceiling` and no longer
     * fall (each above half the one before): the round-off floor of the
     * linear solves, not a slow iteration.
     */
    /** max |current - previous| / max |current| over every process. */
    static double
    relative_change(const FieldVector &previous, const FieldVector &current);

    static bool
    at_roundoff(const std::vector<double> &changes, const double ceiling);

    double relative_tolerance = 1e-10;
    /** What the state vector is, for the log ("stress"; the Gauss-point
     * cone iterates on strains). */
    std::string state_name = "stress";
    /** Changes below this that stop falling are round-off (see above). */
    double       roundoff_ceiling = 1e-8;
    unsigned int maximum_steps    = 100;

  private:
    /** Damps the step from previous to current by the exact line search
     * (above). */
    static void
    line_search(const Operations  &operations,
                const FieldVector &previous,
                FieldVector       &current,
                std::ostream      &log);

    std::vector<double> changes;
    unsigned int        steps            = 0;
    bool                roundoff_limited = false;
  };
} // namespace hrcontact

#endif
