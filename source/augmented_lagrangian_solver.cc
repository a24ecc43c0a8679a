#include <deal.II/base/timer.h>

#include <hrcontact/augmented_lagrangian_solver.h>
#include <hrcontact/input.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace hrcontact
{
  using namespace dealii;

  void
  AugmentedLagrangianSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Augmented Lagrangian");
    prm.declare_entry(
      "Initial penalty",
      "1e4",
      Patterns::Anything(),
      "Initial compliance alpha_0 of every unilateral constraint (an "
      "expression of the constants): with Initial penalty scaling = nodal "
      "compliance, a factor times the nodal compliance of the mesh and "
      "material; with absolute, a length per force. Small against the nodal "
      "compliance ties released nodes to their trial position and slows "
      "convergence (the paper's Fig. 14); large makes the iteration behave "
      "like an active-set method, until the released springs no longer hold "
      "the body.");
    prm.declare_entry(
      "Initial penalty scaling",
      "nodal compliance",
      Patterns::Selection("nodal compliance|absolute"),
      "nodal compliance: alpha_0 = Initial penalty x c_h, with c_h = (1 - "
      "nu^2)/E in plane strain, 1/E in plane stress (length per force per unit "
      "thickness) and 1/(E h) in 3D, h the mean cell size (volume / cells)^(1/3): "
      "the compliance of a boundary node up to a factor of order one, so the "
      "same factor works in any units and on any mesh. absolute: alpha_0 = "
      "Initial penalty as given (the paper's 0.001).");
    prm.declare_entry("Penalty growth factor",
                      "10",
                      Patterns::Double(1),
                      "rho of eq. 49: alpha <- rho alpha when ||pbar|| did not "
                      "fall enough.");
    prm.declare_entry("Penalty update threshold",
                      "0.25",
                      Patterns::Double(0, 1),
                      "delta of eq. 49: alpha grows when ||pbar|| > delta "
                      "||pbar_previous||.");
    prm.declare_entry("Penalty update",
                      "global",
                      Patterns::Selection("global|per constraint"),
                      "global: one alpha for all constraints, updated from "
                      "the norms; per constraint: alpha_i updated from "
                      "|pbar_i|.");
    prm.declare_entry("Minimum inner tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "eps_min of Step 2: each inner Newton solve reduces the "
                      "gradient norm of eq. 46 by the factor eps_k at least "
                      "(or stops earlier when a full step keeps the released "
                      "set: then it is exact).");
    prm.declare_entry("Maximum inner tolerance",
                      "1e-2",
                      Patterns::Double(0),
                      "eps_max of Step 2 (same units as eps_min).");
    prm.declare_entry("Absolute tolerance",
                      "0",
                      Patterns::Double(0),
                      "Stop (Step 6) when ||pbar|| is below this force "
                      "(0: use the relative tolerance only).");
    prm.declare_entry(
      "Relative tolerance",
      "1e-10",
      Patterns::Double(0),
      "Stop (Step 6) when ||pbar|| is below this times the load "
      "scale (the largest of the applied load and the trial "
      "reactions).");
    prm.declare_entry("Maximum multiplier updates",
                      "100",
                      Patterns::Integer(1),
                      "Iteration limit: reaching it is an error (exit code 3), "
                      "but all result files are written with converged = "
                      "false.");
    prm.declare_entry(
      "Maximum penalty growth",
      "1e16",
      Patterns::Double(1),
      "alpha may grow (eq. 49) up to this factor times Initial penalty. "
      "Needing more means the iteration is not converging at any penalty the "
      "mesh can carry (typically Initial penalty far too large against the "
      "nodal compliance): the run stops with an error naming the cause, and "
      "writes its results with converged = false.");
    prm.declare_entry(
      "Regularisation",
      "consistent augmented Lagrangian",
      Patterns::Selection("consistent augmented Lagrangian|pure penalty"),
      "consistent augmented Lagrangian: the paper's eq. 28 with multiplier "
      "updates (eq. 48) and penalty updates (eq. 49). pure penalty: mu stays 0 "
      "and alpha stays Initial penalty; the quadratic piece is solved exactly "
      "once. A released constraint is then a spring of compliance alpha "
      "anchored at the gap, so it carries a tension of about (opening) / "
      "alpha: an error that shrinks only as alpha grows (and the solves "
      "degrade).");
    prm.declare_entry("Maximum Newton steps",
                      "50",
                      Patterns::Integer(1),
                      "Newton steps per multiplier update at most.");
    prm.leave_subsection();
  }

  void
  AugmentedLagrangianSolver::parse_parameters(ParameterHandler &prm,
                                              const Constants  &constants)
  {
    prm.enter_subsection("Augmented Lagrangian");
    initial_penalty =
      evaluate_constant_expression(prm.get("Initial penalty"),
                                   constants,
                                   "Augmented Lagrangian/Initial penalty");
    scale_by_compliance =
      (prm.get("Initial penalty scaling") == "nodal compliance");
    initial_alpha = initial_penalty;
    if (!(initial_penalty > 0))
      throw InputError(
        "Augmented Lagrangian/Initial penalty must be positive.");
    rho                = prm.get_double("Penalty growth factor");
    delta              = prm.get_double("Penalty update threshold");
    per_constraint     = (prm.get("Penalty update") == "per constraint");
    eps_min            = prm.get_double("Minimum inner tolerance");
    eps_max            = prm.get_double("Maximum inner tolerance");
    absolute_tolerance = prm.get_double("Absolute tolerance");
    relative_tolerance = prm.get_double("Relative tolerance");
    max_updates        = prm.get_integer("Maximum multiplier updates");
    max_newton_steps   = prm.get_integer("Maximum Newton steps");
    pure_penalty       = (prm.get("Regularisation") == "pure penalty");
    max_penalty_growth = prm.get_double("Maximum penalty growth");
    prm.leave_subsection();
    if (eps_min > eps_max)
      throw InputError("Augmented Lagrangian: Minimum inner tolerance exceeds "
                       "Maximum inner tolerance.");
  }

  void
  AugmentedLagrangianSolver::set_nodal_compliance(const double c)
  {
    nodal_compliance = c;
    initial_alpha = scale_by_compliance ? initial_penalty * c : initial_penalty;
  }

  bool
  AugmentedLagrangianSolver::solve(const EquilibriumSystem &system,
                                   NewtonStepPath          &path,
                                   const double             load_scale,
                                   std::ostream            &log)
  {
    const unsigned int nq = system.contact_rows.size();
    std::vector<bool>  unilateral(nq);
    for (unsigned int i = 0; i < nq; ++i)
      unilateral[i] = system.rows[system.contact_rows[i]].unilateral;

    Timer timer;
    mu.assign(nq, 0.);
    alpha.assign(nq, initial_alpha);
    released.assign(nq, false);
    history.clear();
    p_history.clear();
    mu_history.clear();
    alpha_history.clear();
    released_history.clear();
    total_newton_steps = 0;
    converged          = false;
    diverged           = false;

    // Step 0: trial solution, every constraint bilateral with w_n = g.
    path.solve(released, mu, alpha, p);
    // The contact force term the last solve balanced: [A](mu - alpha p).
    std::vector<double> balanced(nq, 0.);

    double scale = std::abs(load_scale);
    for (unsigned int i = 0; i < nq; ++i)
      scale = std::max(scale, std::abs(p[i]));
    tolerance_used = std::max(absolute_tolerance, relative_tolerance * scale);
    const double force_scale = std::max(scale, 1e-300);

    auto norm_of = [](const std::vector<double> &v) {
      double sum = 0;
      for (const double x : v)
        sum += x * x;
      return std::sqrt(sum);
    };

    std::vector<double> pbar(nq, 0.), pbar_previous(nq, 0.);
    double              norm_previous = std::numeric_limits<double>::max();
    double              eps_previous  = eps_max;
    double              eps_k         = eps_max;
    unsigned int        newton_steps  = 0;
    std::vector<bool>   released_previous(nq, false);
    bool                last_inner_exact = false;

    log << "  augmented Lagrangian: " << nq << " contact constraints, initial "
        << "alpha " << initial_alpha;
    if (scale_by_compliance)
      log << " (" << initial_penalty << " x nodal compliance "
          << nodal_compliance << ")";
    log << ", tolerance " << std::setprecision(3) << tolerance_used
        << std::endl;

    for (unsigned int k = 1;; ++k)
      {
        // pbar with the multipliers and compliances the solve used.
        for (unsigned int i = 0; i < nq; ++i)
          pbar[i] = unilateral[i] ? std::max(p[i], mu[i] / alpha[i]) : 0.;
        const double norm = norm_of(pbar);

        unsigned int changes = 0;
        for (unsigned int i = 0; i < nq; ++i)
          {
            released[i] = unilateral[i] && (p[i] > mu[i] / alpha[i]);
            changes += (released[i] != released_previous[i]);
          }
        released_previous = released;

        // Step 4: multiplier update (eq. 48); afterwards mu = w_n - g. The
        // pure penalty keeps mu = 0.
        if (!pure_penalty)
          for (unsigned int i = 0; i < nq; ++i)
            mu[i] -= alpha[i] * pbar[i];

        p_history.push_back(p);
        mu_history.push_back(mu);
        alpha_history.push_back(alpha);
        released_history.push_back(released);

        AugmentedLagrangianStep step;
        step.k              = k;
        step.newton_steps   = newton_steps;
        step.alpha_min      = *std::min_element(alpha.begin(), alpha.end());
        step.alpha_max      = *std::max_element(alpha.begin(), alpha.end());
        step.eps_k          = eps_k;
        step.norm_pbar      = norm;
        step.active_changes = changes;
        step.seconds        = timer.wall_time();
        history.push_back(step);
        log << "    update " << std::setw(3) << k << ": Newton steps "
            << std::setw(2) << newton_steps << ", ||pbar|| " << std::scientific
            << std::setprecision(3) << norm << ", alpha [" << step.alpha_min
            << ", " << step.alpha_max << "], eps " << eps_k << std::defaultfloat
            << ", status changes " << changes << std::endl;

        // Step 6: convergence test. The pure penalty is done once the
        // inner solve has reached its exact piece (its own answer, with the
        // tension of the released springs as its error).
        final_norm_pbar = norm;
        if (pure_penalty ? (k > 1 && last_inner_exact) : norm < tolerance_used)
          {
            converged = true;
            break;
          }
        if (k >= max_updates)
          break;
        // A released spring far softer than the mesh (alpha much larger than
        // the nodal compliance) leaves the body all but unsupported: the
        // solves lose every digit and ||pbar|| explodes. Stop, do not iterate
        // on garbage.
        if (!std::isfinite(norm) || norm > 1e6 * force_scale)
          {
            diverged = true;
            break;
          }

        // Step 5: penalty update (eq. 49), within the allowed growth.
        if (k > 1 && !pure_penalty)
          {
            const double alpha_cap = max_penalty_growth * initial_alpha;
            bool         capped    = false;
            if (per_constraint)
              {
                for (unsigned int i = 0; i < nq; ++i)
                  if (std::abs(pbar[i]) > delta * std::abs(pbar_previous[i]))
                    {
                      capped |= (rho * alpha[i] > alpha_cap);
                      alpha[i] *= rho;
                    }
              }
            else if (norm > delta * norm_previous)
              for (double &a : alpha)
                {
                  capped |= (rho * a > alpha_cap);
                  a *= rho;
                }
            if (capped)
              {
                for (double &a : alpha)
                  a = std::min(a, alpha_cap);
                diverged = true;
                break;
              }
          }
        norm_previous = norm;
        pbar_previous = pbar;

        // Step 2: inner tolerance, made unit free with the load scale.
        const double relative_pbar = norm / force_scale;
        eps_k =
          std::max(eps_min,
                   std::min(
                     {eps_max, eps_previous, relative_pbar * relative_pbar}));
        if (pure_penalty)
          eps_k = 0; // solve the piece exactly
        eps_previous = eps_k;

        // Step 3: Newton steps until the gradient, in contact coordinates
        // e = [A](mu - alpha p) - balanced, falls by eps_k. A step that keeps
        // the released set gives e = 0 exactly: the piece is quadratic.
        newton_steps        = 0;
        double initial_norm = 0;
        for (;;)
          {
            std::vector<bool>   active(nq);
            std::vector<double> e(nq), term(nq, 0.);
            for (unsigned int i = 0; i < nq; ++i)
              {
                active[i] = unilateral[i] && p[i] > mu[i] / alpha[i];
                if (active[i])
                  term[i] = mu[i] - alpha[i] * p[i];
                e[i] = term[i] - balanced[i];
              }
            const double e_norm = norm_of(e);
            if (newton_steps == 0)
              initial_norm = e_norm;
            last_inner_exact = (e_norm == 0);
            if (e_norm == 0 ||
                (newton_steps > 0 && e_norm <= eps_k * initial_norm) ||
                newton_steps >= max_newton_steps)
              break;
            path.solve(active, mu, alpha, p);
            for (unsigned int i = 0; i < nq; ++i)
              balanced[i] = active[i] ? mu[i] - alpha[i] * p[i] : 0.;
            ++newton_steps;
            ++total_newton_steps;
          }
      }
    log << "  augmented Lagrangian "
        << (converged ? "converged" : "did NOT converge") << " after "
        << history.size() << " multiplier updates, " << total_newton_steps
        << " Newton steps" << std::endl;
    return converged;
  }
} // namespace hrcontact
