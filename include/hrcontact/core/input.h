#ifndef hrcontact_input_h
#define hrcontact_input_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hrcontact
{
  /**
   * An error in what the user gave us (parameter file, geometry, supports).
   * The executable prints what() and exits with a non-zero code; no result
   * file is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * A solver that stopped without converging (the iteration limit). Every
   * result file has been written, flagged converged = false; the executable
   * exits with code 3.
   */
  class NotConvergedError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The value of a Patterns::Selection entry of the current subsection as
   * an enum, so that names are compared here, once, and nowhere after
   * parsing. `names` pairs every option of the pattern with its value; an
   * option missing from it (the pattern and the list out of step) is an
   * error naming the entry.
   */
  template <typename Enum>
  Enum
  get_selection(dealii::ParameterHandler                        &prm,
                const std::string                               &entry,
                const std::vector<std::pair<std::string, Enum>> &names)
  {
    const std::string value = prm.get(entry);
    for (const auto &[name, e] : names)
      if (name == value)
        return e;
    throw InputError(entry + " = " + value + ": not a known option.");
  }

  /**
   * Named constants usable in every expression of a parameter file, e.g.
   * "L = 10, D = 1, I = D^3/12": later entries may use earlier ones.
   */
  using Constants = std::map<std::string, double>;

  Constants
  parse_constants(const std::string &text, const std::string &where);

  /** Evaluate an expression of constants only (no x, y, z). */
  double
  evaluate_constant_expression(const std::string &expression,
                               const Constants   &constants,
                               const std::string &where);

  /**
   * A FunctionParser for `n_components` expressions separated by ';' in the
   * variables x, y (, z). Syntax errors are reported as InputError naming
   * `where`.
   */
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  make_function(const std::string &expressions,
                const unsigned int n_components,
                const Constants   &constants,
                const std::string &where);

  /**
   * One entry of a per-boundary list such as
   * "0: 0; 0 | 2 y: 1e-3*x": a boundary id, optional components
   * (letters x, y, z) and the expressions after the colon.
   */
  struct BoundaryEntry
  {
    dealii::types::boundary_id boundary_id;
    std::vector<unsigned int>  components;
    std::string                expressions;
  };

  /**
   * Split a per-boundary list. If `allow_components` is false, an entry must
   * not name components. Each id may appear once.
   */
  std::vector<BoundaryEntry>
  parse_boundary_list(const std::string &text,
                      const unsigned int dim,
                      const bool         allow_components,
                      const std::string &where);

  /** A named entry "name: text" of a '|'-separated list. */
  std::vector<std::pair<std::string, std::string>>
  parse_named_list(const std::string &text, const std::string &where);

  /**
   * Whether @p text is one number and nothing else (surrounding blanks
   * aside), and then its value: the entries that take `automatic` or a
   * number (Nested iteration/Coarse levels, Stress tolerance).
   */
  bool
  parse_number(const std::string &text, double &value);

  /** Split at a separator and trim each piece; empty pieces are kept. */
  std::vector<std::string>
  split_and_trim(const std::string &text, const char separator);
} // namespace hrcontact

#endif
