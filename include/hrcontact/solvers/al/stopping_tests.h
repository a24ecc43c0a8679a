#ifndef hrcontact_al_stopping_tests_h
#define hrcontact_al_stopping_tests_h

#include <hrcontact/discretisation/contact_row_partition.h>
#include <hrcontact/solvers/contact_iteration.h>

#include <algorithm>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

namespace hrcontact
{
  /** The entries of v at the given rows: a process's part of a state. */
  template <typename T>
  std::vector<T>
  part_of(const std::vector<T> &v, const std::vector<unsigned int> &rows)
  {
    std::vector<T> part;
    part.reserve(rows.size());
    for (const unsigned int i : rows)
      part.push_back(v[i]);
    return part;
  }

  /**
   * The inner cycle test: the sets (of branches, of rows in contact) an
   * inner Newton iteration has solved, each process keeping the part of its
   * own rows. A piece depends only on its set while the multipliers and
   * penalties stay, so a set solved before means the iteration cycles
   * (SolveOutcome::inner_cycle). A set was solved before when every process
   * finds its part at the same earlier step.
   */
  template <typename Key>
  class SolvedSets
  {
  public:
    explicit SolvedSets(const ContactRowPartition &ownership)
      : ownership(ownership)
    {}
    /** Record key; false if it was solved before. */
    bool
    insert(const Key &key)
    {
      if (!keys.empty())
        {
          std::vector<bool> same(keys.size());
          for (unsigned int j = 0; j < keys.size(); ++j)
            same[j] = (keys[j] == key);
          same = ownership.all(same);
          if (std::find(same.begin(), same.end(), true) != same.end())
            return false;
        }
      keys.push_back(key);
      return true;
    }
    void
    clear()
    {
      keys.clear();
    }

  private:
    const ContactRowPartition &ownership;
    std::vector<Key>           keys;
  };

  /**
   * The periodicity test of the diagonal scheme, a fixed-point map of (mu,
   * alpha): an update that reproduces the branches and penalties of an
   * earlier one exactly and its multipliers to 1e-12 of their largest runs
   * in a cycle (measured: a period of 6 on the bridge stops at alpha_0 =
   * 1e4 c_h; SolveOutcome::periodic).
   */
  class PeriodicityTest
  {
  public:
    explicit PeriodicityTest(const ContactRowPartition &ownership);

    /**
     * Whether this update (this process's rows: branches, alpha, mu)
     * repeats an earlier one on every process; otherwise it is recorded.
     * Collective.
     */
    bool
    repeats(const std::vector<unsigned int> &branches,
            const std::vector<double>       &alpha,
            const std::vector<double>       &mu);

  private:
    const ContactRowPartition &ownership;
    std::vector<std::tuple<std::vector<unsigned int>,
                           std::vector<double>,
                           std::vector<double>>>
      visited;
  };

  /** The divergence test: ||pbar|| not finite or above a million times the
   * force scale (released springs far softer than the mesh). */
  bool
  diverges(const double norm, const double force_scale);

  /** A body that some rigid-body motion leaves held by contact only. */
  struct BodyHeldByContact
  {
    /** For messages: "body 2", ...; empty in a one-body scene. */
    std::string name;
    /** How many of its rigid-body motions only contact holds. */
    unsigned int free_motions = 0;
    /** The contact rows (indices into contact_rows) at its nodes,
     * a pair row at its slave and its master nodes. */
    std::vector<unsigned int> rows;
  };

  /**
   * The floating test: the first of @p bodies whose rows are all free
   * (@p is_free, asked by each process of the rows it owns), or null.
   * Collective.
   */
  const BodyHeldByContact *
  floating_body(const std::vector<BodyHeldByContact>    &bodies,
                const ContactRowPartition               &ownership,
                const std::function<bool(unsigned int)> &is_free);

  /** How the last solve stopped, as the tests found it. */
  struct StopFlags
  {
    bool converged = false, diverged = false, cycled = false, periodic = false,
         floating = false, roundoff_limited = false;
    /** CG's tolerance when the inner iteration cycled at its floor (0: the
     * path solved exactly). */
    double cycle_linear_tolerance = 0;

    /** One outcome, in the order in which the causes explain each other. */
    SolveOutcome
    outcome() const;
  };
} // namespace hrcontact

#endif
