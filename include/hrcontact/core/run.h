#ifndef hrcontact_run_h
#define hrcontact_run_h

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace hrcontact
{
  /** Declare the whole parameter tree (all subsections). */
  void
  declare_all_parameters(dealii::ParameterHandler &prm);

  /**
   * Read a parameter file into prm; bad files throw InputError with a
   * message naming the file, the line and the cause.
   */
  void
  read_parameter_file(dealii::ParameterHandler &prm, const std::string &file);

  /**
   * Run the scene of a parameter file: what the executable does. Returns
   * the exit code (0 on success); errors are printed to err as one clear
   * message, and no result file is written. Under mpirun, process 0 prints
   * and writes; every process returns the same code.
   */
  int
  run_parameter_file(const std::string &file,
                     std::ostream      &log,
                     std::ostream      &err);
} // namespace hrcontact

#endif
