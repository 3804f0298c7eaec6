#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameter_text.h>
#include <thinlayer/parameters/parameters.h>

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

// The Reference section: the closed form a run is compared with, and what
// a verification scene expects of its run.

namespace thinlayer
{
  void
  ReferenceParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference");
    prm.declare_entry(
      "Analytic load",
      "",
      Patterns::Anything(),
      "Closed-form value the final load is compared with, as an "
      "expression of the geometry parameters and the Variables (e.g. "
      "'1/(sin(alpha*pi/180)*cos(alpha*pi/180))'); empty for none, or for "
      "the middle of the Analytic bracket.");
    prm.declare_entry(
      "Variables",
      "",
      Patterns::Anything(),
      "Names for the Analytic load bound to numeric entries of the run: "
      "'name = Section/Entry; ...' (e.g. 'phi = Material 2/Friction "
      "angle'), each the value this run has (a sweep's or the command "
      "line's), so that a sweep over a material property compares every "
      "run with its own closed form. Empty: none.");
    prm.declare_entry(
      "Analytic bracket",
      "",
      Patterns::Anything(),
      "Two numbers 'low, high' known to hold the exact value where no "
      "closed form is (e.g. the lower and upper bounds of limit analysis): "
      "written into summary.json (reference_bracket) for the tests and the "
      "report; without an Analytic load, its middle is the analytic "
      "load. Empty: none.");
    prm.declare_entry(
      "Expected outcome",
      "",
      Patterns::Anything(),
      "The outcome a run of this scene must end in (collapse, plateau, "
      "completed or not converged), for scenes that verify a closed form: "
      "a run that ends otherwise is reported and exits with status 4. "
      "Empty: any.");
    prm.declare_entry(
      "Expected load range",
      "",
      Patterns::Anything(),
      "Two numbers 'low, high': the run's load (its collapse load where it "
      "has one, else its last converged load) must lie in [low, high] "
      "times the analytic load (in load units where there is none), or "
      "the run is reported and exits with status 4. Empty: not checked.");
    prm.leave_subsection();
  }


  void
  ReferenceParameters::parse(ParameterHandler     &prm,
                             const std::string    &file,
                             const MeshParameters &mesh)
  {
    prm.enter_subsection("Reference");
    const std::string expression = prm.get("Analytic load");
    const std::string bound      = prm.get("Variables");
    const std::string bracket    = Utilities::trim(prm.get("Analytic bracket"));
    expected_outcome             = Utilities::trim(prm.get("Expected outcome"));
    const std::string range = Utilities::trim(prm.get("Expected load range"));
    prm.leave_subsection();

    auto constants = mesh.geometry_parameters;
    for (const auto &[name, value] : variables(prm, bound, file))
      if (!constants.emplace(name, value).second)
        throw InputError(file,
                         "Reference/Variables",
                         "'" + name +
                           "' is a geometry parameter too; expected a name "
                           "of its own");
    if (Utilities::trim(expression).empty() &&
        constants.size() > mesh.geometry_parameters.size())
      throw InputError(file,
                       "Reference/Variables",
                       "names values for the Analytic load, which is "
                       "empty; expected an Analytic load that uses them, "
                       "or no Variables");
    analytic_load = evaluate_analytic_load(expression, constants, file);
    parse_bracket(bracket, file);

    if (!expected_outcome.empty() && expected_outcome != "collapse" &&
        expected_outcome != "plateau" && expected_outcome != "completed" &&
        expected_outcome != "not converged")
      throw InputError(file,
                       "Reference/Expected outcome",
                       "expected collapse, plateau, completed, not converged "
                       "or nothing, got '" +
                         expected_outcome + "'");
    if (!range.empty())
      {
        const auto ends = Utilities::split_string_list(range, ',');
        if (ends.size() != 2 || !to_number(ends[0], expected_low) ||
            !to_number(ends[1], expected_high) ||
            !(expected_low <= expected_high))
          throw InputError(file,
                           "Reference/Expected load range",
                           "expected two numbers 'low, high' with low <= "
                           "high, got '" +
                             range + "'");
      }
  }


  double
  ReferenceParameters::evaluate_analytic_load(
    const std::string                   &expression,
    const std::map<std::string, double> &constants,
    const std::string                   &file)
  {
    if (Utilities::trim(expression).empty())
      return std::numeric_limits<double>::quiet_NaN();
    check_expressions(expression,
                      1,
                      "x,y,unused_z",
                      constants,
                      file,
                      "Reference/Analytic load");
    // A closed form of the geometry only: x and y are no variables of it
    // (they would silently be 0).
    FunctionParser<2> f(1);
    auto              with_pi = constants;
    with_pi["pi"]             = numbers::PI;
    const SilencedErrorStream silence;
    double                    value;
    try
      {
        f.initialize("unused_reference_x,unused_reference_y",
                     expression,
                     with_pi);
        value = f.value(Point<2>());
      }
    catch (const ExceptionBase &e)
      {
        throw InputError(file,
                         "Reference/Analytic load",
                         "expected an expression of the geometry "
                         "parameters, the Variables and pi only (no x "
                         "or y): " +
                           message_of(e));
      }
    if (!std::isfinite(value) || value == 0)
      throw InputError(file,
                       "Reference/Analytic load",
                       "expected a finite, non-zero value, got " +
                         std::to_string(value));
    return value;
  }


  void
  ReferenceParameters::parse_bracket(const std::string &text,
                                     const std::string &file)
  {
    analytic_bracket.clear();
    if (text.empty())
      return;
    const auto ends = Utilities::split_string_list(text, ',');
    double     low = 0, high = 0;
    if (ends.size() != 2 || !to_number(ends[0], low) ||
        !to_number(ends[1], high) || !std::isfinite(low) ||
        !std::isfinite(high) || !(low < high) || low * high <= 0)
      throw InputError(file,
                       "Reference/Analytic bracket",
                       "expected two finite numbers 'low, high' of one "
                       "sign with low < high, got '" +
                         text + "'");
    analytic_bracket = {{"low", low}, {"high", high}};
    if (!std::isfinite(analytic_load))
      analytic_load = (low + high) / 2;
    else if (analytic_load < low || analytic_load > high)
      throw InputError(file,
                       "Reference/Analytic bracket",
                       "[" + text + "] does not hold the Analytic load " +
                         std::to_string(analytic_load) +
                         "; expected a bracket around it");
  }


  std::map<std::string, double>
  ReferenceParameters::variables(ParameterHandler  &prm,
                                 const std::string &text,
                                 const std::string &file)
  {
    std::map<std::string, double> values;
    const std::string             entry = "Reference/Variables";
    if (Utilities::trim(text).empty())
      return values;
    // The entries this run declares, by their paths.
    std::ostringstream listing;
    prm.print_parameters(listing, ParameterHandler::ShortPRM);
    std::set<std::string> declared;
    for (const auto &[line, path] :
         set_entries(parameter_lines(listing.str(), file)))
      declared.insert(path);
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto        equal = item.find('=');
        const std::string name =
          Utilities::trim(item.substr(0, std::min(equal, item.size())));
        if (equal == std::string::npos || !is_identifier(name))
          throw InputError(file,
                           entry,
                           "expected 'name = Section/Entry; ...' with a "
                           "name of letters, digits and underscores, got '" +
                             item + "'");
        if (values.count(name) != 0 || name == "pi")
          throw InputError(file,
                           entry,
                           "'" + name +
                             "' is named twice or is pi; expected each name "
                             "once");
        const std::string path  = entry_path(item.substr(equal + 1));
        const auto        parts = Utilities::split_string_list(path, '/');
        if (parts.size() < 2)
          throw InputError(file,
                           entry,
                           "expected '" + name + " = Section/Entry', got '" +
                             item + "'");
        // Only a declared entry is read: deal.II's debug library stops the
        // program on a get() of any other.
        std::string value;
        if (declared.count(path) != 0)
          {
            for (unsigned int k = 0; k + 1 < parts.size(); ++k)
              prm.enter_subsection(parts[k]);
            value = prm.get(parts.back());
            for (unsigned int k = 0; k + 1 < parts.size(); ++k)
              prm.leave_subsection();
          }
        double number = 0;
        if (!to_number(value, number) || !std::isfinite(number))
          throw InputError(file,
                           entry,
                           "'" + name + " = " + path +
                             "': expected an entry of this run with a "
                             "number as its value, got " +
                             (value.empty() ? std::string("none")
                                            : "'" + value + "'"));
        values[name] = number;
      }
    return values;
  }
} // namespace thinlayer
