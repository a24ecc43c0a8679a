#ifndef hrcontact_memory_log_h
#define hrcontact_memory_log_h

#include <deal.II/base/mpi.h>

#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace hrcontact
{
  /**
   * The resident memory of the largest process after each stage of a run,
   * printed with Output/Print timing: where the memory of a run goes (the
   * figure of doc/benchmarks.md's memory per process).
   */
  class MemoryLog
  {
  public:
    explicit MemoryLog(const MPI_Comm communicator);

    /** Record the resident and peak memory of the largest process now
     * (collective). */
    void
    mark(const std::string &stage);

    /** The table of stages, resident MB and peak MB so far. */
    void
    print(std::ostream &log) const;

  private:
    MPI_Comm communicator;
    /** (stage, resident MB of the largest process, peak MB so far). */
    std::vector<std::tuple<std::string, double, double>> marks;
  };
} // namespace hrcontact

#endif
