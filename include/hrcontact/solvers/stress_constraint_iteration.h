#ifndef hrcontact_stress_constraint_iteration_h
#define hrcontact_stress_constraint_iteration_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/discretisation/field_vector.h>

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  /**
   * The consistent augmented Lagrangian of a stress constraint (no tension,
   * no compression; StressConstraint), the paper's Steps 1-6 with the
   * multipliers at the cell vertices (StressConstraintField):
   *
   * - Step 2: the material Newton iteration (MaterialIteration) solves the
   *   problem at fixed multipliers mu and penalty alpha, to the inner
   *   tolerance eps_k = max(tol, min(eps_{k-1}, (||r_k|| / ||s||)^2)),
   *   eps_0 = 1e-2;
   * - Step 4: mu <- P(mu + alpha sigma) (eq. 48); the residual r = max |mu
   *   change| / alpha is in stress units;
   * - Step 5: alpha <- 10 alpha if ||r|| > ||r_prev|| / 4 (eq. 49);
   * - Step 6: stop when ||r|| <= Relative tolerance x max |s| and the last
   *   inner solve's stress change was as small (exact for a linear law at
   *   points that stay in the cone: a load that needs no tension costs two
   *   solves).
   *
   * A load only stresses outside the cone could carry has no solution: mu
   * then grows without bound and alpha with it; past Maximum penalty x the
   * initial one, or after Maximum updates, the run stops with a
   * NotConvergedError that names the largest violation.
   */
  class StressConstraintIteration
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** What the problem that owns the path and the field does. */
    struct Operations
    {
      /** The material iteration to this relative tolerance, from the
       * current linearisation (its first step a solve); returns its Newton
       * steps and its last relative stress change. */
      std::function<std::pair<unsigned int, double>(double)> solve_material;
      /** The stresses of the last solve (owned and ghost cells). */
      std::function<void(FieldVector &)> stresses;
      /** The multiplier update; returns the residual (stress units). */
      std::function<double(const FieldVector &)> update_multipliers;
      /** Sets the penalty (a compliance). */
      std::function<void(double)> set_penalty;
      /** The largest violation of the constraint by these stresses. */
      std::function<double(const FieldVector &)> violation;
      /** F_c and d_c at these stresses and the current multipliers. */
      std::function<void(const FieldVector &)> linearise_at;
    };

    /**
     * Steps 1-6. `compliance` scales the initial penalty (the elastic
     * compliance 1/E of the material). Logs one line per update.
     */
    void
    solve(const Operations &operations,
          const double      compliance,
          std::ostream     &log);

    /** Relative residuals max |r_k| / max |s| per update. */
    const std::vector<double> &
    residual_history() const
    {
      return residuals;
    }
    /** The penalty of each update. */
    const std::vector<double> &
    penalty_history() const
    {
      return penalties;
    }
    /** The material Newton steps of each inner solve. */
    const std::vector<unsigned int> &
    inner_step_history() const
    {
      return inner_steps;
    }
    /** Multiplier updates taken. */
    unsigned int
    n_updates() const
    {
      return residuals.size();
    }

    double       initial_penalty    = 100;
    double       relative_tolerance = 1e-10;
    unsigned int maximum_updates    = 50;
    double       maximum_penalty    = 1e8;
    /** Constraint points: "cell centres", "Gauss points" or "vertices". */
    std::string constraint_points = "vertices";
    /** How the cone is imposed (Method). */
    enum class Method
    {
      /** The interior point where it applies, else the augmented
       * Lagrangian (MaterialLoop::method). */
      automatic,
      /** This class: multipliers at the Constraint points. */
      augmented_lagrangian,
      /** GaussPointCone: in closed form at the Gauss points. */
      closed_form_projection,
      /** GaussPointCone with a log barrier driven to zero (BarrierPath). */
      interior_point
    };
    Method method = Method::automatic;
    /** The closed-form projection's residual stiffness (GaussPointCone). */
    double residual_stiffness = 1e-4;
    /** The Gauss-point methods' tolerance on the model's stresses; 0:
     * automatic (MaterialLoop: 1e-6 closed form, 1e-4 interior point). */
    double stress_tolerance = 0;

  private:
    std::vector<double>       residuals, penalties;
    std::vector<unsigned int> inner_steps;
  };
} // namespace hrcontact

#endif
