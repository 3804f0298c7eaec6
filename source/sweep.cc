#include <thinlayer/input_error.h>
#include <thinlayer/run.h>
#include <thinlayer/sweep.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /// The overrides that make run @p combination of the sweep.
    std::vector<std::string>
    overrides_for(const Parameters                &base,
                  const std::vector<unsigned int> &combination,
                  const std::string               &directory)
    {
      std::vector<std::string> overrides;
      auto                     geometry       = base.geometry_parameters;
      bool                     geometry_swept = false;
      for (unsigned int k = 0; k < base.sweep.size(); ++k)
        {
          const auto &[name, values] = base.sweep[k];
          const std::string &value   = values[combination[k]];
          if (name.find('/') != std::string::npos)
            overrides.push_back(name + "=" + value);
          else
            {
              geometry[name] = std::stod(value);
              geometry_swept = true;
            }
        }
      if (geometry_swept)
        {
          std::ostringstream text;
          text.precision(17);
          for (const auto &[name, value] : geometry)
            text << (text.tellp() > 0 ? ", " : "") << name << '=' << value;
          overrides.push_back("Mesh/Geometry parameters=" + text.str());
        }
      overrides.push_back("Sweep/Values=");
      overrides.push_back("Output/Directory=" + directory);
      overrides.push_back("Output/Print timing=false");
      return overrides;
    }

    /// A CSV field, quoted where it holds a comma or a quote (RFC 4180).
    std::string
    csv_text(const std::string &text)
    {
      if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += (c == '"')    ? std::string("\"\"")
                  : (c == '\n') ? std::string(" ")
                                : std::string(1, c);
      return quoted + "\"";
    }

    std::string
    csv_number(const double value)
    {
      if (!std::isfinite(value))
        return "";
      char buffer[32];
      std::snprintf(buffer, sizeof(buffer), "%.10g", value);
      return buffer;
    }
  } // namespace


  void
  run_sweep(const std::string              &file,
            const std::vector<std::string> &overrides,
            const Parameters               &base,
            std::ostream                   &out)
  {
    // All combinations, first name slowest.
    std::vector<std::vector<unsigned int>> combinations(1);
    for (const auto &[name, values] : base.sweep)
      {
        std::vector<std::vector<unsigned int>> extended;
        for (const auto &c : combinations)
          for (unsigned int v = 0; v < values.size(); ++v)
            {
              extended.push_back(c);
              extended.back().push_back(v);
            }
        combinations.swap(extended);
      }

    // "alpha=30, Solver/Tolerance=1e-3": the values of run r.
    const auto describe = [&](const unsigned int r) {
      std::string values;
      for (unsigned int k = 0; k < base.sweep.size(); ++k)
        values += (k ? ", " : "") + base.sweep[k].first + "=" +
                  base.sweep[k].second[combinations[r][k]];
      return values;
    };

    const auto directory_of = [&](const unsigned int run) {
      char name[32];
      std::snprintf(name, sizeof(name), "/run-%03u", run + 1);
      return base.output_directory + name;
    };

    // Check every run's parameters before anything is written.
    std::vector<std::vector<std::string>> run_overrides;
    for (unsigned int r = 0; r < combinations.size(); ++r)
      {
        run_overrides.push_back(overrides);
        for (const auto &o :
             overrides_for(base, combinations[r], directory_of(r)))
          run_overrides.back().push_back(o);
        try
          {
            ParameterReader().read(file, run_overrides.back());
          }
        catch (const InputError &e)
          {
            throw InputError(file,
                             "Sweep/Values",
                             "the run with " + describe(r) +
                               " is invalid: " + e.what());
          }
      }

    std::filesystem::create_directories(base.output_directory);
    std::ofstream csv(base.output_directory + "/sweep.csv");
    csv << "run";
    for (const auto &[name, values] : base.sweep)
      csv << ',' << csv_text(name);
    csv << ",converged,last_converged_load,first_failed_load,reference_load,"
           "relative_error,cells,dofs,equations,load_steps,total_iterations,"
           "wall_seconds,warnings,error\n";

    out << "thinlayer: sweep of " << combinations.size() << " runs into "
        << base.output_directory << '\n';
    for (unsigned int r = 0; r < combinations.size(); ++r)
      {
        const std::string values = describe(r);

        csv << r + 1;
        for (unsigned int k = 0; k < base.sweep.size(); ++k)
          csv << ',' << csv_text(base.sweep[k].second[combinations[r][k]]);

        std::ostringstream run_output;
        try
          {
            const Parameters p = ParameterReader().read(file, run_overrides[r]);
            const RunSummary s = run_scene(p, run_output);
            csv << ',' << (s.converged ? 1 : 0) << ','
                << csv_number(s.last_converged_load) << ','
                << csv_number(s.first_failed_load) << ','
                << csv_number(s.reference_load) << ','
                << csv_number(s.relative_error) << ',' << s.cells << ','
                << s.dofs << ',' << s.equations << ',' << s.load_steps << ','
                << s.total_iterations << ',' << csv_number(s.wall_seconds)
                << ',' << csv_text(s.warnings) << ",\n";

            char line[160];
            std::snprintf(line,
                          sizeof(line),
                          "last converged load %.5g%s, %u iterations to it",
                          s.last_converged_load,
                          s.converged ? "" : " (then failed)",
                          s.converged_iterations);
            out << "  run " << r + 1 << '/' << combinations.size() << ": "
                << values << ": " << line;
            if (std::isfinite(s.relative_error))
              {
                std::snprintf(line,
                              sizeof(line),
                              ", relative error %+.3e",
                              s.relative_error);
                out << line;
              }
            if (!s.warnings.empty())
              out << " (" << s.warnings << ')';
            out << std::endl; // progress: one line per run, as it ends
          }
        catch (const std::exception &e)
          {
            csv << ",0,,,,,,,,,,,," << csv_text(e.what()) << '\n';
            out << "  run " << r + 1 << '/' << combinations.size() << ": "
                << values << ": error: " << e.what() << std::endl;
          }
        csv << std::flush;
      }
    out << "  results in " << base.output_directory << "/sweep.csv\n";
  }
} // namespace thinlayer
