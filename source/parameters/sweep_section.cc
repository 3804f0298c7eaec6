#include <deal.II/base/utilities.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/parameters/parameter_checks.h>
#include <thinlayer/parameters/parameter_text.h>
#include <thinlayer/parameters/parameters.h>

#include <cmath>

// The Sweep section: the values a scene is rerun for, checked as they are
// read.

namespace thinlayer
{
  namespace
  {
    std::vector<std::pair<std::string, std::vector<std::string>>>
    parse_sweep(const std::string &text, const std::string &file)
    {
      std::vector<std::pair<std::string, std::vector<std::string>>> sweep;
      for (const auto &item : Utilities::split_string_list(text, ';'))
        {
          const auto  equal = item.find('=');
          std::string key =
            Utilities::trim(item.substr(0, std::min(equal, item.size())));
          if (key.find('/') != std::string::npos)
            key = entry_path(key);
          if (equal == std::string::npos || key.empty() ||
              (key.find('/') == std::string::npos && !is_identifier(key)))
            throw InputError(file,
                             "Sweep/Values",
                             "expected 'name = v1, v2, ...' (a geometry "
                             "parameter or Section/Entry), got '" +
                               item + "'");
          if (key == "Output/Directory" || key == "Sweep/Values" ||
              key == "Mesh/Trust geometry scripts")
            throw InputError(file,
                             "Sweep/Values",
                             "'" + key + "' cannot be swept: " +
                               (key == "Sweep/Values"
                                  ? std::string("a sweep does not sweep "
                                                "itself")
                                : key == "Output/Directory"
                                  ? std::string("every run of a sweep "
                                                "writes into run-NNN of the "
                                                "sweep's directory")
                                  : std::string("only the command line can "
                                                "trust a geometry script")));
          for (const auto &[earlier, v] : sweep)
            if (earlier == key)
              throw InputError(file,
                               "Sweep/Values",
                               "'" + key +
                                 "' is named twice; expected each name "
                                 "once, with all its values");
          // Values are comma-separated; braces group a value that is a
          // list itself ("Kinematics/Harmonics = {1}, {1, 3}").
          std::vector<std::string> values;
          std::string              current;
          int                      depth = 0;
          for (const char ch : item.substr(equal + 1) + ",")
            {
              if (ch == '{')
                ++depth;
              else if (ch == '}')
                --depth;
              else if (ch == ',' && depth == 0)
                {
                  if (!Utilities::trim(current).empty())
                    values.push_back(Utilities::trim(current));
                  current.clear();
                }
              else
                current += ch;
            }
          if (depth != 0)
            throw InputError(file,
                             "Sweep/Values",
                             "unbalanced braces in '" + item + "'");
          if (values.empty())
            throw InputError(file,
                             "Sweep/Values",
                             "expected at least one value for '" + key + "'");
          if (key.find('/') == std::string::npos)
            for (const auto &v : values)
              {
                double number = 0;
                if (!to_number(v, number) || !std::isfinite(number))
                  throw InputError(file,
                                   "Sweep/Values",
                                   "expected numbers for the geometry "
                                   "parameter '" +
                                     key + "', got '" + v + "'");
              }
          sweep.emplace_back(key, values);
        }
      std::size_t runs = 1;
      for (const auto &[name, values] : sweep)
        if ((runs *= values.size()) > SweepParameters::max_runs)
          throw InputError(file,
                           "Sweep/Values",
                           "the combinations make more than " +
                             std::to_string(SweepParameters::max_runs) +
                             " runs; expected at most that many (split "
                             "the sweep)");
      return sweep;
    }
  } // namespace


  void
  SweepParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Sweep");
    prm.declare_entry(
      "Values",
      "",
      Patterns::Anything(),
      "Rerun the scene for every combination of values: "
      "'name = v1, v2, ...; name = ...'. A name with a '/' is an entry "
      "('Solver/Tolerance = 1e-3, 1e-6'), any other a geometry parameter "
      "('alpha = 10, 20, 30'). Braces group a value that is a list "
      "('Kinematics/Harmonics = {1}, {1, 3}'). Each run writes into run-NNN "
      "of the output "
      "directory, and sweep.csv there gets one row per run; at most " +
        std::to_string(max_runs) + " runs. Empty: one run.");
    prm.leave_subsection();
  }


  void
  SweepParameters::parse(ParameterHandler &prm, const std::string &file)
  {
    prm.enter_subsection("Sweep");
    values = parse_sweep(prm.get("Values"), file);
    prm.leave_subsection();
  }
} // namespace thinlayer
