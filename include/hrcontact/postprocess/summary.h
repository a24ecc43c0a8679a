#ifndef hrcontact_summary_h
#define hrcontact_summary_h

#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

namespace hrcontact
{
  /** Ordered "key = value" lines of summary.txt (doc/design.md, outputs). */
  class Summary
  {
  public:
    void
    add(const std::string &key, const std::string &value);
    void
    add(const std::string &key, const double value);
    /** Value of a key; throws if absent. */
    std::string
    get(const std::string &key) const;
    double
    get_double(const std::string &key) const;
    /** Write atomically (temporary file, then rename). */
    void
    write(const std::string &filename) const;

    std::vector<std::pair<std::string, std::string>> entries;
  };

  /** Write a file atomically: whole or not at all. */
  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer);

  /**
   * The same on process 0 of the communicator only: every process holds the
   * replicated results, one writes them.
   */
  void
  write_file_atomically(const MPI_Comm                             communicator,
                        const std::string                         &filename,
                        const std::function<void(std::ostream &)> &writer);
} // namespace hrcontact

#endif
