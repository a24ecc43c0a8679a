#include <deal.II/base/utilities.h>

#include <hrcontact/core/memory_log.h>

#include <iomanip>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  MemoryLog::MemoryLog(const MPI_Comm communicator)
    : communicator(communicator)
  {}

  void
  MemoryLog::mark(const std::string &stage)
  {
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    marks.emplace_back(stage,
                       Utilities::MPI::max(stats.VmRSS / 1024., communicator),
                       Utilities::MPI::max(stats.VmHWM / 1024., communicator));
  }

  void
  MemoryLog::print(std::ostream &log) const
  {
    std::ostringstream table;
    table << "resident memory after each stage (MB, largest process):\n";
    for (const auto &[stage, resident, peak] : marks)
      table << "  " << std::left << std::setw(36) << stage << std::right
            << std::setw(10) << std::fixed << std::setprecision(0) << resident
            << "   (peak so far " << peak << ")\n";
    log << table.str() << std::flush;
  }
} // namespace hrcontact
