#include <deal.II/base/timer.h>

#include <deal.II/lac/lapack_full_matrix.h>

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
    prm.declare_entry("Initial penalty",
                      "1e-3",
                      Patterns::Anything(),
                      "Initial compliance alpha_0 of every unilateral "
                      "constraint (length per force; an expression of the "
                      "constants). Small against the nodal compliance of the "
                      "mesh ties released nodes to their trial position and "
                      "slows convergence (the paper's Fig. 14); large makes "
                      "the iteration behave like an active-set method.");
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
    initial_alpha =
      evaluate_constant_expression(prm.get("Initial penalty"),
                                   constants,
                                   "Augmented Lagrangian/Initial penalty");
    if (!(initial_alpha > 0))
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
    prm.leave_subsection();
    if (eps_min > eps_max)
      throw InputError("Augmented Lagrangian: Minimum inner tolerance exceeds "
                       "Maximum inner tolerance.");
  }

  void
  AugmentedLagrangianSolver::compute_p(const EquilibriumReduction &reduction)
  {
    const unsigned int nq = reduction.n_contact_rows();
    const unsigned int m  = reduction.n_self_equilibrated();
    p.resize(nq);
    for (unsigned int i = 0; i < nq; ++i)
      {
        const double *q   = reduction.QR_row(i);
        double        sum = reduction.contact_offset()[i];
        for (unsigned int j = 0; j < m; ++j)
          sum += q[j] * s0[j];
        p[i] = sum;
      }
  }

  bool
  AugmentedLagrangianSolver::solve(const EquilibriumSystem    &system,
                                   const EquilibriumReduction &reduction,
                                   const double                load_scale,
                                   std::ostream               &log)
  {
    const unsigned int nq = reduction.n_contact_rows();
    const unsigned int m  = reduction.n_self_equilibrated();
    std::vector<bool>  unilateral(nq);
    for (unsigned int i = 0; i < nq; ++i)
      unilateral[i] = system.rows[system.contact_rows[i]].unilateral;

    Timer timer;
    // Z = M0^{-1} (QR)^T (m x nq) and S = QR Z (nq x nq), kept for the
    // Woodbury solves: M0 does not change during the iteration.
    std::vector<double> Z(static_cast<std::size_t>(m) * nq);
    for (unsigned int i = 0; i < nq; ++i)
      std::copy(reduction.QR_row(i),
                reduction.QR_row(i) + m,
                Z.begin() + static_cast<std::size_t>(i) * m);
    reduction.solve_M0(Z.data(), nq);
    FullMatrix<double> S(nq, nq);
    for (unsigned int i = 0; i < nq; ++i)
      for (unsigned int j = 0; j < nq; ++j)
        {
          const double *q   = reduction.QR_row(i);
          const double *z   = Z.data() + static_cast<std::size_t>(j) * m;
          double        sum = 0;
          for (unsigned int k = 0; k < m; ++k)
            sum += q[k] * z[k];
          S(i, j) = sum;
        }

    const Vector<double> &b0      = reduction.linear_term();
    const double          b0_norm = std::max(b0.l2_norm(), 1e-300);
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

    // Step 0: trial solution, every constraint bilateral with w_n = g.
    s0 = b0;
    reduction.solve_M0(s0.data());
    compute_p(reduction);

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

    log << "  augmented Lagrangian: " << nq << " contact constraints, initial "
        << "alpha " << initial_alpha << ", tolerance " << std::setprecision(3)
        << tolerance_used << std::endl;

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

        // Step 4: multiplier update (eq. 48); afterwards mu = w_n - g.
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

        // Step 6: convergence test.
        final_norm_pbar = norm;
        if (norm < tolerance_used)
          {
            converged = true;
            break;
          }
        if (k >= max_updates)
          break;

        // Step 5: penalty update (eq. 49).
        if (k > 1)
          {
            if (per_constraint)
              {
                for (unsigned int i = 0; i < nq; ++i)
                  if (std::abs(pbar[i]) > delta * std::abs(pbar_previous[i]))
                    alpha[i] *= rho;
              }
            else if (norm > delta * norm_previous)
              for (double &a : alpha)
                a *= rho;
          }
        norm_previous = norm;
        pbar_previous = pbar;

        // Step 2: inner tolerance, made unit free with the load scale.
        const double relative_pbar = norm / force_scale;
        eps_k =
          std::max(eps_min,
                   std::min(
                     {eps_max, eps_previous, relative_pbar * relative_pbar}));
        eps_previous = eps_k;

        // Step 3: Newton on s0 until ||grad|| <= eps_k ||grad at the start||.
        newton_steps = 0;
        Vector<double>            grad(m), M0s0(m), direction(m);
        std::vector<unsigned int> previous_active;
        double                    initial_grad_norm = 0;
        for (;;)
          {
            compute_p(reduction);
            std::vector<unsigned int> active;
            for (unsigned int i = 0; i < nq; ++i)
              if (unilateral[i] && p[i] > mu[i] / alpha[i])
                active.push_back(i);
            // A full Newton step that kept the released set is exact: the
            // functional is quadratic on that piece. What gradient is left is
            // round-off, whatever eps_k asks.
            if (newton_steps > 0 && active == previous_active)
              break;
            previous_active = active;
            // grad = -M0 s0 + b0 + sum_active q_i (mu_i - alpha_i p_i)
            reduction.multiply_M0(s0, M0s0);
            grad = b0;
            grad -= M0s0;
            for (const unsigned int i : active)
              {
                const double  c = mu[i] - alpha[i] * p[i];
                const double *q = reduction.QR_row(i);
                for (unsigned int j = 0; j < m; ++j)
                  grad[j] += c * q[j];
              }
            // Step 3's tolerance as a reduction of the gradient within this
            // inner solve: unit free, and every update makes progress.
            const double grad_norm = grad.l2_norm();
            if (newton_steps == 0)
              initial_grad_norm = grad_norm;
            if (grad_norm <= eps_k * initial_grad_norm ||
                grad_norm <= 1e-15 * b0_norm ||
                newton_steps >= max_newton_steps)
              break;

            // direction = H^{-1} grad, H = M0 + sum_active alpha_i q_i q_i^T:
            // Woodbury with y = M0^{-1} grad,
            // direction = y - Z_A (alpha_A^{-1} + S_AA)^{-1} (QR_A y).
            direction = grad;
            reduction.solve_M0(direction.data());
            if (!active.empty())
              {
                const unsigned int       na = active.size();
                LAPACKFullMatrix<double> W(na, na);
                Vector<double>           rhs(na);
                for (unsigned int a = 0; a < na; ++a)
                  {
                    for (unsigned int b = 0; b < na; ++b)
                      W(a, b) = S(active[a], active[b]);
                    W(a, a) += 1. / alpha[active[a]];
                    const double *q   = reduction.QR_row(active[a]);
                    double        sum = 0;
                    for (unsigned int j = 0; j < m; ++j)
                      sum += q[j] * direction[j];
                    rhs[a] = sum;
                  }
                W.set_property(LAPACKSupport::symmetric);
                W.compute_cholesky_factorization();
                W.solve(rhs);
                for (unsigned int a = 0; a < na; ++a)
                  {
                    const double *z =
                      Z.data() + static_cast<std::size_t>(active[a]) * m;
                    for (unsigned int j = 0; j < m; ++j)
                      direction[j] -= rhs[a] * z[j];
                  }
              }
            s0 += direction;
            ++newton_steps;
            ++total_newton_steps;
          }
        compute_p(reduction);
      }
    log << "  augmented Lagrangian "
        << (converged ? "converged" : "did NOT converge") << " after "
        << history.size() << " multiplier updates, " << total_newton_steps
        << " Newton steps" << std::endl;
    return converged;
  }
} // namespace hrcontact
