#include <hrcontact/solvers/al/stopping_tests.h>

#include <cmath>

namespace hrcontact
{
  PeriodicityTest::PeriodicityTest(const ContactRowPartition &ownership)
    : ownership(ownership)
  {}

  bool
  PeriodicityTest::repeats(const std::vector<unsigned int> &branches,
                           const std::vector<double>       &a_here,
                           const std::vector<double>       &m_here)
  {
    // Each process compares the rows it sees; an earlier update matches
    // when it matches on every process.
    double mu_scale = 0;
    for (const double m : m_here)
      mu_scale = std::max(mu_scale, std::abs(m));
    mu_scale = ownership.max(mu_scale);
    std::vector<bool>   same(visited.size());
    std::vector<double> difference(visited.size(), 0.);
    for (unsigned int j = 0; j < visited.size(); ++j)
      {
        const auto &[b, a, m] = visited[j];
        same[j]               = (b == branches && a == a_here);
        for (unsigned int r = 0; r < m.size(); ++r)
          difference[j] = std::max(difference[j], std::abs(m[r] - m_here[r]));
      }
    bool periodic = false;
    if (!visited.empty())
      {
        same = ownership.all(same);
        for (unsigned int j = 0; j < visited.size(); ++j)
          {
            const double largest = ownership.max(difference[j]);
            periodic |= same[j] && largest <= 1e-12 * mu_scale;
          }
      }
    if (!periodic)
      visited.emplace_back(branches, a_here, m_here);
    return periodic;
  }

  bool
  diverges(const double norm, const double force_scale)
  {
    return !std::isfinite(norm) || norm > 1e6 * force_scale;
  }

  const BodyHeldByContact *
  floating_body(const std::vector<BodyHeldByContact>    &bodies,
                const ContactRowPartition               &ownership,
                const std::function<bool(unsigned int)> &is_free)
  {
    // Each process asks about the rows it owns.
    for (const BodyHeldByContact &body : bodies)
      if (ownership.all(std::all_of(
            body.rows.begin(), body.rows.end(), [&](const unsigned int i) {
              return !ownership.is_owned(i) || is_free(i);
            })))
        return &body;
    return nullptr;
  }

  SolveOutcome
  StopFlags::outcome() const
  {
    return floating         ? SolveOutcome::floating :
           roundoff_limited ? SolveOutcome::roundoff_limited :
           periodic         ? SolveOutcome::periodic :
           cycled           ? SolveOutcome::inner_cycle :
           diverged         ? SolveOutcome::diverged :
           converged        ? SolveOutcome::converged :
                              SolveOutcome::iteration_limit;
  }
} // namespace hrcontact
