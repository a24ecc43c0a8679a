#ifndef hrcontact_barrier_path_h
#define hrcontact_barrier_path_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <ostream>

namespace hrcontact
{
  /**
   * The interior-point path of a stress constraint at the Gauss points
   * (Stress constraint iteration/Method = interior point, doc/materials.md).
   *
   * Each point's complementary energy gains the cone's log barrier -tau log
   * det(delta I - s sigma) (StressConstraint::barrier_projection, delta the
   * Tension allowance). For tau > 0 the point law is smooth and strictly
   * monotone, so the displacement problem is smooth and strictly convex and
   * Newton's method converges on it quadratically (the Barrier residual
   * stiffness, in the tangent only, just keeps the solves regular), every
   * stress strictly inside the shifted cone. Its answer misses the constrained
   * one by at most the duality gap, tau per direction and unit volume (sigma :
   * mu = -dim tau at every point). The path drives tau to zero: Initial
   * barrier, times Barrier reduction per stage, each stage Newton's method from
   * the last one's strains, to Final barrier, where the stage is solved to
   * Stress tolerance. tau is in units of s^2 / E, s the largest stress of the
   * elastic step.
   */
  class BarrierPath
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * The stages: set_barrier(t) relinearises at the current strains with
     * tau = t s^2 / E, solve_stage(tolerance) runs Newton's method to that
     * model stress error and returns its steps. The stages run from t =
     * @p first (a carried level: Final barrier or Carried initial barrier).
     */
    void
    run(const std::function<void(double)>               &set_barrier,
        const std::function<unsigned int(const double)> &solve_stage,
        const double                                     stress_tolerance,
        const double                                     first,
        std::ostream                                    &log);

    double initial_barrier = 1e-2;
    /** Where a carried level's path starts over from a rejected start. */
    double carried_barrier = 1e-4;
    double reduction       = 0.1;
    double final_barrier   = 1e-8;
    /** Intermediate stages stop at this model stress error (relative). */
    double stage_tolerance = 1e-1;
    /** Tension allowed, in units of s. */
    double allowance = 1e-6;
    /** Added to the tangent, in units of C. */
    double residual_stiffness = 1e-8;
  };
} // namespace hrcontact

#endif
