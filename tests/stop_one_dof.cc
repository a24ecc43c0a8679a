// The two-sided stop of section 2.4.2 on one degree of freedom: a spring of
// stiffness K to the ground, a load f, and the stop on the node. By hand:
//   f/K in (g-, g+):             u = f/K,                     p = 0
//   f in [K g+, K g+ - p0-]:     u = g+,                      p = K g+ - f
//   f >  K g+ - p0-:             u = (f + p0- + k- g+)/(K + k-), p = K u - f
//   f in [K g- - p0+, K g-]:     u = g-,                      p = K g- - f
//   f <  K g- - p0+:             u = (f + p0+ + k+ g-)/(K + k+), p = K u - f
// The system is built by hand (one stress = the spring force s, F = 1/K,
// B = 1, p = s - f) and solved by the AugmentedLagrangianSolver on both
// Newton-step paths, in both schemes, with constant limit reactions and with
// linear branches. Also checks, for every law, that the envelope L is C^1
// with dL/dp = mu - alpha pbar and that the piece gives that same w - g.

#include <deal.II/base/mpi.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <hrcontact/constraints/constraint_law.h>
#include <hrcontact/solvers/al/augmented_lagrangian_solver.h>
#include <hrcontact/solvers/condensed/condensed_step.h>
#include <hrcontact/solvers/equilibrium_reduction.h>
#include <hrcontact/solvers/null_space_step.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <tuple>

using namespace hrcontact;

namespace
{
  const double K = 2;

  void
  build(EquilibriumSystem                          &system,
        const double                                f,
        const std::shared_ptr<const ConstraintLaw> &law)
  {
    system.dim                    = 1;
    system.n_displacement_dofs    = 1;
    system.n_stress_dofs          = 1;
    system.cell_stress_dofs       = {{0}};
    system.cell_displacement_dofs = {{0}};
    system.cell_flexibility.assign(1, dealii::FullMatrix<double>(1, 1));
    system.cell_flexibility[0](0, 0) = 1. / K;
    dealii::DynamicSparsityPattern dsp(1, 1);
    dsp.add(0, 0);
    system.sparsity.copy_from(dsp);
    system.B.reinit(system.sparsity);
    system.B.set(0, 0, 1.);
    system.load.reinit(1);
    system.load[0] = f;
    EquilibriumRow row;
    row.row_class   = RowClass::contact;
    row.combination = {{0, 1.}};
    row.value       = 0;
    row.law         = law;
    system.rows     = {row};
    system.free_rows.clear();
    system.prescribed_rows.clear();
    system.contact_rows = {0};
    system.node_coordinates.reinit(1);
    system.node_coordinates.compress();
  }

  /** The hand solution (u, p) of the header. */
  std::pair<double, double>
  by_hand(const TwoSidedStop &s, const double f)
  {
    double u;
    if (f / K > s.g_minus && f / K < s.g_plus)
      u = f / K;
    else if (f >= K * s.g_plus && f <= K * s.g_plus - s.p0_minus)
      u = s.g_plus;
    else if (f > K * s.g_plus - s.p0_minus)
      u = (f + s.p0_minus + s.k_minus * s.g_plus) / (K + s.k_minus);
    else if (f >= K * s.g_minus - s.p0_plus)
      u = s.g_minus;
    else
      u = (f + s.p0_plus + s.k_plus * s.g_minus) / (K + s.k_plus);
    return {u, K * u - f};
  }

  /** Envelope checks of one law at a few (p, mu, alpha). */
  void
  check_envelope(const ConstraintLaw &law)
  {
    double worst_derivative = 0, worst_piece = 0;
    for (const double alpha : {0.3, 1., 7.})
      for (const double mu : {-2.5, -0.7, 0., 0.4, 1.5, 3.})
        for (double p = -9; p <= 9; p += 0.37)
          {
            const double h = 1e-6;
            const double derivative =
              (law.regularised_potential(p + h, mu, alpha) -
               law.regularised_potential(p - h, mu, alpha)) /
              (2 * h);
            const double g = law.gradient(p, mu, alpha);
            worst_derivative =
              std::max(worst_derivative, std::abs(derivative - g));
            worst_piece =
              std::max(worst_piece,
                       std::abs(law.piece(p, mu, alpha).relation(p) - g));
          }
    std::cout << "  " << law.name() << ": |dL/dp - (mu - alpha pbar)| "
              << (worst_derivative < 1e-4 ? "< 1e-4" : "TOO LARGE")
              << ", |piece w - g - dL/dp| "
              << (worst_piece < 1e-12 ? "< 1e-12" : "TOO LARGE") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(6);

  std::cout << "Envelope of each law (eq. 26 generalised):" << std::endl;
  check_envelope(UnilateralContact());
  check_envelope(MacaulayUnilateralContact());
  check_envelope(BilateralConstraint());
  check_envelope(TwoSidedStop(-1, 2, -3, 4));
  check_envelope(TwoSidedStop(-1, 2, -3, 4, 0.5, 1.5));

  // g- = -1, g+ = 2, p0- = -3, p0+ = 4 with K = 2: the branches change at
  // f = -6, -2, 4, 7.
  for (const auto &[title, k_minus, k_plus] :
       {std::tuple<const char *, double, double>{"constant limits", 0., 0.},
        std::tuple<const char *, double, double>{"linear branches", 0.5, 1.5}})
    {
      auto stop = std::make_shared<TwoSidedStop>(-1, 2, -3, 4, k_minus, k_plus);
      std::cout << "\n"
                << title << " (" << stop->name() << ", k- " << k_minus
                << ", k+ " << k_plus << "):" << std::endl;
      for (const double f : {-9., -6.5, -4., -2.5, 1., 3., 4.5, 6., 9., 12.})
        for (const std::string scheme : {"classical", "diagonal"})
          for (const std::string path_name : {"null-space", "condensed"})
            {
              EquilibriumSystem system;
              build(system, f, stop);
              AugmentedLagrangianSolver solver;
              solver.diagonal = (scheme == "diagonal");
              solver.set_nodal_compliance(1. / K);
              std::ostringstream              log;
              std::unique_ptr<NewtonStepPath> path;
              EquilibriumReduction            reduction;
              if (path_name == "null-space")
                {
                  reduction.initialize(system);
                  path = std::make_unique<NullSpaceStep>(reduction);
                }
              else
                path = std::make_unique<CondensedStep>(system);
              const bool converged =
                solver.solve(system, *path, std::abs(f), log);
              const double u    = solver.result().opening[0]; // w - g, g = 0
              const double p    = solver.result().p[0];
              const auto   hand = by_hand(*stop, f);
              const bool   ok =
                converged &&
                std::abs(u - hand.first) < 1e-8 * (1 + std::abs(f)) &&
                std::abs(p - hand.second) < 1e-8 * (1 + std::abs(f));
              if (scheme == "classical" && path_name == "null-space")
                std::cout << "  f = " << std::setw(5) << f
                          << ": u = " << std::setw(9) << hand.first
                          << ", p = " << std::setw(9) << hand.second
                          << ", branch '"
                          << stop->branch_name(solver.result().pieces[0].branch)
                          << "'" << std::endl;
              std::cout << "    " << std::setw(9) << scheme << ", "
                        << std::setw(10) << path_name << ": "
                        << (ok ? "matches the hand solution" : "WRONG")
                        << ", updates " << solver.result().history.size()
                        << ", Newton steps "
                        << solver.result().total_newton_steps;
              if (!ok)
                std::cout << " (u = " << u << ", p = " << p << ")";
              std::cout << std::endl;
            }
    }

  // Bad parameters are named input errors.
  std::cout << "\nBad parameters:" << std::endl;
  for (const auto &[gm, gp, pm, pp, km] :
       {std::tuple<double, double, double, double, double>{1, -1, -1, 1, 0},
        std::tuple<double, double, double, double, double>{-1, 1, 1, 1, 0},
        std::tuple<double, double, double, double, double>{-1, 1, -1, 1, -2}})
    try
      {
        TwoSidedStop s(gm, gp, pm, pp, km);
        std::cout << "  accepted: WRONG" << std::endl;
      }
    catch (const InputError &e)
      {
        std::cout << "  " << e.what() << std::endl;
      }
}
