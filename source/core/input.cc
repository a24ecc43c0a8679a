#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/vector.h>

#include <hrcontact/core/input.h>

#include <cmath>
#include <iostream>
#include <set>
#include <sstream>

namespace hrcontact
{
  using namespace dealii;

  namespace
  {
    std::string
    deal_ii_message(const ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      return Utilities::trim(s.str());
    }
  } // namespace

  bool
  parse_number(const std::string &text, double &value)
  {
    std::size_t used = 0;
    try
      {
        value = std::stod(text, &used);
      }
    catch (const std::exception &)
      {
        return false;
      }
    return text.find_first_not_of(" \t", used) == std::string::npos;
  }

  std::vector<std::string>
  split_and_trim(const std::string &text, const char separator)
  {
    std::vector<std::string> pieces;
    std::string              current;
    for (const char c : text)
      if (c == separator)
        {
          pieces.push_back(Utilities::trim(current));
          current.clear();
        }
      else
        current += c;
    pieces.push_back(Utilities::trim(current));
    return pieces;
  }

  Constants
  parse_constants(const std::string &text, const std::string &where)
  {
    Constants constants;
    if (Utilities::trim(text).empty())
      return constants;
    for (const std::string &item : split_and_trim(text, ','))
      {
        const auto eq = item.find('=');
        if (item.empty() || eq == std::string::npos)
          throw InputError(
            where + ": expected 'name = expression' but found '" + item + "'.");
        const std::string name = Utilities::trim(item.substr(0, eq));
        const std::string expr = Utilities::trim(item.substr(eq + 1));
        if (name.empty() ||
            !(std::isalpha(static_cast<unsigned char>(name[0])) ||
              name[0] == '_'))
          throw InputError(where + ": '" + name +
                           "' is not a valid constant name.");
        for (const char c : name)
          if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
            throw InputError(where + ": '" + name +
                             "' is not a valid constant name.");
        if (name == "x" || name == "y" || name == "z")
          throw InputError(where + ": '" + name +
                           "' is a coordinate and cannot be a constant.");
        constants[name] =
          evaluate_constant_expression(expr,
                                       constants,
                                       where + ", constant '" + name + "'");
      }
    return constants;
  }

  double
  evaluate_constant_expression(const std::string &expression,
                               const Constants   &constants,
                               const std::string &where)
  {
    const auto   f     = make_function<1>(expression, 1, constants, where);
    const double value = f->value(Point<1>());
    if (!std::isfinite(value))
      throw InputError(where + ": the expression '" + expression +
                       "' does not evaluate to a finite number.");
    return value;
  }

  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  make_function(const std::string &expressions,
                const unsigned int n_components,
                const Constants   &constants,
                const std::string &where)
  {
    const std::vector<std::string> pieces = split_and_trim(expressions, ';');
    if (pieces.size() != n_components)
      throw InputError(where + ": expected " + std::to_string(n_components) +
                       " expression(s) separated by ';' but found " +
                       std::to_string(pieces.size()) + " in '" + expressions +
                       "'.");
    for (const std::string &p : pieces)
      if (p.empty())
        throw InputError(where + ": empty expression in '" + expressions +
                         "'.");

    const std::string variables = (dim == 1 ? "x" : dim == 2 ? "x,y" : "x,y,z");
    auto              f = std::make_unique<FunctionParser<dim>>(n_components);
    // deal.II prints muparser's raw diagnostic to std::cerr before it
    // throws; keep it out of the user's console, our message says it better.
    std::ostringstream    muparser_noise;
    std::streambuf *const cerr_buffer = std::cerr.rdbuf(muparser_noise.rdbuf());
    struct RestoreCerr
    {
      std::streambuf *buffer;
      ~RestoreCerr()
      {
        std::cerr.rdbuf(buffer);
      }
    } restore{cerr_buffer};
    try
      {
        Constants with_pi = constants;
        with_pi.emplace("pi", numbers::PI);
        f->initialize(variables, pieces, with_pi);
        // muparser compiles lazily: evaluate once to surface syntax errors
        // and unknown names here, with the entry's name, not deep in a loop.
        Vector<double> values(n_components);
        f->vector_value(Point<dim>(), values);
      }
    catch (const ExceptionBase &e)
      {
        throw InputError(where + ": cannot parse '" + expressions +
                         "': " + deal_ii_message(e));
      }
    catch (const std::exception &e)
      {
        throw InputError(where + ": cannot parse '" + expressions +
                         "': " + e.what());
      }
    return f;
  }

  std::vector<BoundaryEntry>
  parse_boundary_list(const std::string &text,
                      const unsigned int dim,
                      const bool         allow_components,
                      const std::string &where)
  {
    std::vector<BoundaryEntry> entries;
    if (Utilities::trim(text).empty())
      return entries;
    std::set<types::boundary_id> seen;
    for (const std::string &item : split_and_trim(text, '|'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw InputError(where + ": entry '" + item +
                           "' lacks the ':' after the boundary id.");
        std::istringstream head(item.substr(0, colon));
        long               id = -1;
        if (!(head >> id) || id < 0 ||
            id >= static_cast<long>(numbers::internal_face_boundary_id))
          throw InputError(where + ": entry '" + item +
                           "' does not start with a boundary id.");
        BoundaryEntry entry;
        entry.boundary_id = static_cast<types::boundary_id>(id);
        std::string letters;
        head >> letters;
        std::string extra;
        if (head >> extra)
          throw InputError(where + ": cannot read '" + item.substr(0, colon) +
                           "' as 'id [components]'.");
        if (!letters.empty() && !allow_components)
          throw InputError(
            where + ": entry '" + item +
            "' names components, which this list does not take.");
        for (const char c : letters)
          {
            const unsigned int comp = (c == 'x' ? 0 :
                                       c == 'y' ? 1 :
                                       c == 'z' ? 2 :
                                                  99);
            if (comp >= dim)
              throw InputError(where + ": '" + std::string(1, c) +
                               "' is not a displacement component in " +
                               std::to_string(dim) + "D (use x, y" +
                               (dim == 3 ? ", z" : "") + ").");
            for (const unsigned int existing : entry.components)
              if (existing == comp)
                throw InputError(where + ": component '" + std::string(1, c) +
                                 "' appears twice in '" + item + "'.");
            entry.components.push_back(comp);
          }
        if (entry.components.empty() && allow_components)
          for (unsigned int d = 0; d < dim; ++d)
            entry.components.push_back(d);
        entry.expressions = Utilities::trim(item.substr(colon + 1));
        if (!seen.insert(entry.boundary_id).second)
          throw InputError(where + ": boundary id " + std::to_string(id) +
                           " appears twice.");
        entries.push_back(entry);
      }
    return entries;
  }

  std::vector<std::pair<std::string, std::string>>
  parse_named_list(const std::string &text, const std::string &where)
  {
    std::vector<std::pair<std::string, std::string>> entries;
    if (Utilities::trim(text).empty())
      return entries;
    std::set<std::string> seen;
    for (const std::string &item : split_and_trim(text, '|'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw InputError(where + ": entry '" + item +
                           "' lacks the ':' after its name.");
        const std::string name = Utilities::trim(item.substr(0, colon));
        if (name.empty() || name.find_first_of(" \t=,") != std::string::npos)
          throw InputError(where + ": '" + name +
                           "' is not a valid name (no blanks, '=' or ',').");
        if (!seen.insert(name).second)
          throw InputError(where + ": the name '" + name + "' appears twice.");
        entries.emplace_back(name, Utilities::trim(item.substr(colon + 1)));
      }
    return entries;
  }

  template std::unique_ptr<FunctionParser<1>>
  make_function<1>(const std::string &,
                   const unsigned int,
                   const Constants &,
                   const std::string &);
  template std::unique_ptr<FunctionParser<2>>
  make_function<2>(const std::string &,
                   const unsigned int,
                   const Constants &,
                   const std::string &);
  template std::unique_ptr<FunctionParser<3>>
  make_function<3>(const std::string &,
                   const unsigned int,
                   const Constants &,
                   const std::string &);
} // namespace hrcontact
