#ifndef hrcontact_row_relinearisation_h
#define hrcontact_row_relinearisation_h

#include <vector>

namespace hrcontact
{
  class NewtonStepPath;

  /**
   * Constraint rows that depend on the configuration (curved obstacles,
   * linearised at the nearest point of their surface): the augmented
   * Lagrangian solver calls relinearise() explicitly between multiplier
   * updates. The implementation rewrites the rows it owns in the
   * EquilibriumSystem and tells the path through
   * NewtonStepPath::rows_changed(); no other code changes rows during a
   * solve (doc/design.md, "Constraint sources").
   */
  class RowRelinearisation
  {
  public:
    virtual ~RowRelinearisation() = default;

    /**
     * Linearise again at the configuration of the path's last solve, with
     * w_n = g + opening on the Q rows. Returns whether a row changed beyond
     * round-off: the solver then solves at least once more and waits for a
     * call that changes nothing before it converges.
     */
    virtual bool
    relinearise(NewtonStepPath &path, const std::vector<double> &opening) = 0;
  };
} // namespace hrcontact

#endif
