// The stopping and cycle tests of the augmented Lagrangian
// (solvers/al/stopping_tests.h), each alone on hand-made states:
//  - SolvedSets (the inner cycle test) finds a set solved before, and
//    forgets after clear();
//  - PeriodicityTest (the diagonal scheme's cycle test) finds an update
//    that repeats an earlier one's branches and penalties exactly and its
//    multipliers to 1e-12 of their largest, and no other;
//  - diverges: a norm that is not finite or above 1e6 force scales;
//  - floating_body: the first body whose rows are all free;
//  - StopFlags::outcome: one SolveOutcome, the causes in the order in
//    which they explain each other.

#include <deal.II/base/mpi.h>

#include <hrcontact/solvers/al/stopping_tests.h>

#include <iostream>
#include <limits>

#include "tests.h"

using namespace hrcontact;

std::string
yes(const bool b)
{
  return b ? "yes" : "no";
}

const char *
name(const SolveOutcome o)
{
  switch (o)
    {
      case SolveOutcome::converged:
        return "converged";
      case SolveOutcome::iteration_limit:
        return "iteration limit";
      case SolveOutcome::diverged:
        return "diverged";
      case SolveOutcome::inner_cycle:
        return "inner cycle";
      case SolveOutcome::periodic:
        return "periodic";
      case SolveOutcome::floating:
        return "floating";
      case SolveOutcome::roundoff_limited:
        return "round-off limited";
    }
  return "?";
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const ContactRowPartition                rows(3);

  SolvedSets<std::vector<unsigned int>> sets(rows);
  std::cout << "SolvedSets: new set recorded: " << yes(sets.insert({0, 1, 0}))
            << ", another: " << yes(sets.insert({1, 1, 0}))
            << ", the first again recorded: " << yes(sets.insert({0, 1, 0}));
  sets.clear();
  std::cout << ", after clear: " << yes(sets.insert({0, 1, 0})) << std::endl;

  PeriodicityTest           periodicity(rows);
  const std::vector<double> alpha = {1e-3, 1e-2, 1e-3}, mu = {0.5, -2., 1e-4};
  auto                      scaled = [&](const double factor) {
    std::vector<double> m = mu;
    m[1] *= factor;
    return m;
  };
  std::cout << "PeriodicityTest: first update repeats: "
            << yes(periodicity.repeats({0, 1, 1}, alpha, mu))
            << "\n  other branches: "
            << yes(periodicity.repeats({1, 1, 1}, alpha, mu))
            << "\n  other penalty: "
            << yes(periodicity.repeats({0, 1, 1}, {1e-3, 1e-1, 1e-3}, mu))
            << "\n  multipliers 1e-10 apart: "
            << yes(periodicity.repeats({0, 1, 1}, alpha, scaled(1 + 1e-10)))
            << "\n  multipliers 2e-13 apart (repeats): "
            << yes(periodicity.repeats({0, 1, 1}, alpha, scaled(1 + 1e-13)))
            << std::endl;

  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::cout << "diverges: NaN " << yes(diverges(nan, 1.)) << ", infinity "
            << yes(diverges(std::numeric_limits<double>::infinity(), 1.))
            << ", 2e6 x scale " << yes(diverges(2e8, 1e2)) << ", 1e5 x scale "
            << yes(diverges(1e7, 1e2)) << std::endl;

  const std::vector<BodyHeldByContact> bodies = {{"body 1", 2, {0, 1}},
                                                 {"body 2", 1, {2}}};
  auto floating = [&](const std::vector<bool> &free) {
    const BodyHeldByContact *body =
      floating_body(bodies, rows, [&](const unsigned int i) {
        return bool(free[i]);
      });
    return body ? body->name : std::string("none");
  };
  std::cout << "floating_body: row 2 free: " << floating({false, false, true})
            << "; rows 0, 1 free: " << floating({true, true, false})
            << "; row 0 free: " << floating({true, false, false}) << std::endl;

  auto outcome = [](const std::function<void(StopFlags &)> &set) {
    StopFlags flags;
    set(flags);
    return name(flags.outcome());
  };
  std::cout << "StopFlags: none: " << outcome([](StopFlags &) {})
            << "; converged: "
            << outcome([](StopFlags &f) { f.converged = true; })
            << "; periodic and cycled: "
            << outcome([](StopFlags &f) { f.periodic = f.cycled = true; })
            << "; cycled: " << outcome([](StopFlags &f) { f.cycled = true; })
            << "; floating and diverged: "
            << outcome([](StopFlags &f) { f.floating = f.diverged = true; })
            << "; round-off and cycled: " << outcome([](StopFlags &f) {
                 f.roundoff_limited = f.cycled = true;
               })
            << "; diverged and converged: "
            << outcome([](StopFlags &f) { f.diverged = f.converged = true; })
            << std::endl;
}
