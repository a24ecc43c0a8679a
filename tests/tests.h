// Small helpers shared by the test programs (deal.II's own tests.h is not
// installed with the library).
#ifndef hrcontact_tests_h
#define hrcontact_tests_h

#include <deal.II/base/parameter_handler.h>

#include <hrcontact/hr_problem.h>
#include <hrcontact/run.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace hrcontact_tests
{
  /** Build and solve a problem from parameter text (no files written). */
  template <int dim>
  std::unique_ptr<hrcontact::HRProblem<dim>>
  solve_from_text(const std::string &text)
  {
    dealii::ParameterHandler prm;
    hrcontact::declare_all_parameters(prm);
    prm.parse_input_from_string(text);
    auto problem = std::make_unique<hrcontact::HRProblem<dim>>(prm);
    std::ostringstream quiet;
    problem->solve(quiet);
    return problem;
  }

  /** Read a file into a string. */
  inline std::string
  read_file(const std::string &name)
  {
    std::ifstream      in(name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /** "yes" if value <= bound: prints a check that can fail. */
  inline std::string
  check(const double value, const double bound)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(3) << value;
    return (value <= bound) ? "yes" : "NO (value " + s.str() + ")";
  }
} // namespace hrcontact_tests

#endif
