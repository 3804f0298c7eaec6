#include <deal.II/base/function_parser.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_checks.h>

#include <cctype>
#include <iostream>
#include <sstream>

namespace thinlayer
{

  std::string
  message_of(const ExceptionBase &exception)
  {
    std::ostringstream out;
    exception.print_info(out);
    // deal.II lays its messages out over indented lines; one line reads
    // better after our "error in 'file', entry '...':" prefix.
    std::string text;
    for (const char c : out.str())
      if (!std::isspace(static_cast<unsigned char>(c)))
        text += c;
      else if (!text.empty() && text.back() != ' ')
        text += ' ';
    while (!text.empty() && text.back() == ' ')
      text.pop_back();
    return text;
  }


  void
  check_expressions(const std::string                   &expressions,
                    const unsigned int                   n_components,
                    const std::string                   &variables,
                    const std::map<std::string, double> &constants,
                    const std::string                   &file,
                    const std::string                   &entry)
  {
    const auto parts = Utilities::split_string_list(expressions, ';');
    if (parts.size() != 1 && parts.size() != n_components)
      throw InputError(file,
                       entry,
                       "expected " + std::to_string(n_components) +
                         " expressions separated by ';' (or one for all), "
                         "got " +
                         std::to_string(parts.size()));
    // muParser reads "a, b" outside a function's parentheses as its comma
    // operator, whose value is b: a decimal comma ("-1,5") would silently
    // be 5.
    for (const auto &p : parts)
      {
        int depth = 0;
        for (const char c : p)
          if (c == '(')
            ++depth;
          else if (c == ')')
            --depth;
          else if (c == ',' && depth <= 0)
            throw InputError(file,
                             entry,
                             "'" + p +
                               "' has a comma outside a function's "
                               "parentheses, which the expression parser "
                               "reads as an operator whose value is the "
                               "part after it; write a decimal point (1.5, "
                               "not 1,5) and separate components with ';'");
      }
    const SilencedErrorStream silence;
    try
      {
        FunctionParser<3> f(1);
        auto              all_constants = constants;
        all_constants["pi"]             = numbers::PI;
        for (const auto &p : parts)
          {
            f.initialize(variables, p, all_constants);
            (void)f.value(Point<3>(1, 0, 0));
          }
      }
    catch (const ExceptionBase &e)
      {
        std::string names;
        for (const auto &v : Utilities::split_string_list(variables, ','))
          if (v.rfind("unused", 0) != 0)
            names += (names.empty() ? "" : ", ") + v;
        throw InputError(file,
                         entry,
                         "expected function expressions of " + names +
                           " and the geometry parameters: " + message_of(e));
      }
  }


  bool
  to_number(const std::string &text, double &value)
  {
    try
      {
        std::size_t used = 0;
        value            = std::stod(text, &used);
        return used == text.size() && !text.empty();
      }
    catch (const std::exception &)
      {
        return false;
      }
  }


  bool
  is_identifier(const std::string &name)
  {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0])))
      return false;
    for (const char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        return false;
    return true;
  }


  double
  positive(const ParameterHandler &prm,
           const std::string      &name,
           const std::string      &file,
           const std::string      &section,
           const double            maximum)
  {
    const double value = prm.get_double(name);
    if (!(value > 0))
      throw InputError(file,
                       section + "/" + name,
                       "expected a value > 0, got " + prm.get(name));
    if (!(value <= maximum))
      throw InputError(file,
                       section + "/" + name,
                       "expected a value in (0, " +
                         Utilities::to_string(maximum) + "], got " +
                         prm.get(name));
    return value;
  }


  void
  check_dilation_angle(const ParameterHandler &prm,
                       const std::string      &file,
                       const std::string      &section)
  {
    if (prm.get_double("Dilation angle") > prm.get_double("Friction angle"))
      throw InputError(file,
                       section + "/Dilation angle",
                       "expected at most the friction angle (" +
                         prm.get("Friction angle") + "), got " +
                         prm.get("Dilation angle"));
  }
} // namespace thinlayer
