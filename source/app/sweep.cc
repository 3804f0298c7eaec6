#include <deal.II/base/timer.h>

#include <thinlayer/app/run.h>
#include <thinlayer/app/sweep.h>
#include <thinlayer/base/input_error.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/output/reference_check.h>
#include <thinlayer/output/results_directory.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameter_text.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
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
      auto                     geometry       = base.mesh.geometry_parameters;
      bool                     geometry_swept = false;
      for (unsigned int k = 0; k < base.sweep.values.size(); ++k)
        {
          const auto &[name, values] = base.sweep.values[k];
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


    /// All combinations of the sweep's values, first name slowest.
    std::vector<std::vector<unsigned int>>
    all_combinations(const SweepParameters &sweep)
    {
      std::vector<std::vector<unsigned int>> combinations(1);
      for (const auto &[name, values] : sweep.values)
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
      return combinations;
    }


    /// "alpha=30, Solver/Tolerance=1e-3": the values of @p combination.
    std::string
    describe(const SweepParameters           &sweep,
             const std::vector<unsigned int> &combination)
    {
      std::string values;
      for (unsigned int k = 0; k < sweep.values.size(); ++k)
        values += (k ? ", " : "") + sweep.values[k].first + "=" +
                  sweep.values[k].second[combination[k]];
      return values;
    }


    /// One line of progress for a finished run: its outcome, and its
    /// collapse load where it has one.
    void
    print_run(const RunSummary &s,
              const bool        print_iterations,
              std::ostream     &out)
    {
      out << s.outcome;
      if (std::isfinite(s.collapse_load))
        out << ", collapse load "
            << text_format::printf("%.5g", s.collapse_load);
      else
        out << ", last converged load "
            << text_format::printf("%.5g", s.last_converged_load);
      if (print_iterations)
        out << ", " << s.converged_iterations << " iterations to it";
      if (std::isfinite(s.relative_error))
        out << ", relative error "
            << text_format::printf("%+.3e", s.relative_error);
      if (!s.warnings.empty())
        out << " (" << s.warnings << ')';
      out << std::endl; // progress: one line per run, as it ends
    }


    /// The overrides of one run, checked: an InputError naming the run's
    /// values if they make an invalid scene.
    std::vector<std::string>
    checked_overrides(const std::string               &file,
                      const std::vector<std::string>  &overrides,
                      const Parameters                &base,
                      const std::vector<unsigned int> &combination,
                      const std::string               &directory)
    {
      // The run's own values replace the command line's for the same
      // entries (Sweep/Values, Output/Directory, a swept entry).
      const std::vector<std::string> own =
        overrides_for(base, combination, directory);
      const auto path_of = [](const std::string &o) {
        return entry_path(o.substr(0, o.find('=')));
      };
      std::vector<std::string> result;
      for (const auto &o : overrides)
        if (std::none_of(own.begin(), own.end(), [&](const std::string &r) {
              return path_of(r) == path_of(o);
            }))
          result.push_back(o);
      result.insert(result.end(), own.begin(), own.end());
      try
        {
          ParameterReader().read(file, result);
        }
      catch (const InputError &e)
        {
          throw InputError(file,
                           "Sweep/Values",
                           "the run with " + describe(base.sweep, combination) +
                             " is invalid: " + e.what());
        }
      return result;
    }


    /**
     * One run of the sweep into @p directory (inside the sweep's staging
     * directory; @p named is where it will be): its row of sweep.csv and
     * its line on screen. Returns false if it ended in an error, which is
     * then the row's last field; a run that ended in an error leaves no
     * files. A full disk or a signal while meshing ends the whole sweep.
     */
    bool
    run_one(const std::string              &file,
            const std::vector<std::string> &overrides,
            const std::string              &directory,
            const std::string              &named,
            std::ostream                   &csv,
            std::ostream                   &out,
            unsigned int                   &missed_references)
    {
      std::ostringstream run_output;
      try
        {
          const Parameters p = ParameterReader().read(file, overrides);
          const RunSummary s = run_scene_in(p, directory, run_output);
          csv << ',' << s.csv_row() << ",\n";
          print_run(s, p.output.print_iterations, out);
          if (const ReferenceCheck check = check_reference(p.reference, s);
              check.checked)
            {
              out << "    reference check " << check.description << '\n';
              missed_references += check.passed ? 0 : 1;
            }
          return true;
        }
      catch (const Interrupted &e)
        {
          // While meshing: this run has nothing, the runs before it stay.
          std::error_code error;
          if (mpi::is_root())
            std::filesystem::remove_all(directory, error);
          csv << ',' << RunSummary::csv_error_row() << ','
              << text_format::csv_field(e.what()) << '\n';
          out << e.what() << std::endl;
          return true;
        }
      catch (const WriteError &e)
        {
          throw WriteError(std::string(e.what()) + " (Output/Directory '" +
                           named + "')");
        }
      catch (const std::exception &e)
        {
          std::error_code error;
          if (mpi::is_root())
            std::filesystem::remove_all(directory, error);
          csv << ',' << RunSummary::csv_error_row() << ','
              << text_format::csv_field(e.what()) << '\n';
          out << "error: " << e.what() << std::endl;
          return false;
        }
    }
  } // namespace


  SweepResult
  run_sweep(const std::string              &file,
            const std::vector<std::string> &overrides,
            const Parameters               &base,
            std::ostream                   &out)
  {
    const SweepParameters &sweep        = base.sweep;
    const auto             combinations = all_combinations(sweep);
    const auto             directory_of = [&](const unsigned int run) {
      char name[32];
      std::snprintf(name, sizeof(name), "/run-%03u", run + 1);
      return base.output.directory + name;
    };

    // Check every run's parameters before anything is written (a few
    // milliseconds each): stopped by a signal, and with progress every two
    // seconds where there are many (a small sweep's screen output stays
    // the same however busy the machine).
    std::vector<std::vector<std::string>> run_overrides;
    Timer                                 since_progress;
    for (unsigned int r = 0; r < combinations.size(); ++r)
      {
        if (interrupted())
          throw Interrupted("while checking the sweep's runs");
        if (combinations.size() >= 100 && since_progress.wall_time() > 2)
          {
            out << "  checking the sweep's runs: " << r << '/'
                << combinations.size() << std::endl;
            since_progress.restart();
          }
        run_overrides.push_back(checked_overrides(
          file, overrides, base, combinations[r], directory_of(r)));
      }

    // The whole sweep is one run of its directory: written aside, put in
    // place at the end. Rank 0 writes it (every rank writes its pieces of
    // the fields into the same runs' directories).
    std::unique_ptr<ResultsDirectory> results;
    const std::string                 staging = mpi::on_root([&]() {
      results = std::make_unique<ResultsDirectory>(base.output.directory, file);
      return results->staging();
    });
    std::ofstream                     csv_file;
    std::ostringstream                elsewhere;
    if (results)
      csv_file.open(staging + "/sweep.csv");
    std::ostream &csv = results ? static_cast<std::ostream &>(csv_file)
                                : static_cast<std::ostream &>(elsewhere);
    csv << "run";
    for (const auto &[name, values] : sweep.values)
      csv << ',' << text_format::csv_field(name);
    csv << ',' << RunSummary::csv_header() << ",error\n";

    out << "thinlayer: sweep of " << combinations.size() << " runs into "
        << base.output.directory << '\n';
    for (const std::string &warning : base.warnings)
      out << "  warning: " << warning << '\n';
    SweepResult result;
    for (unsigned int r = 0; r < combinations.size(); ++r)
      {
        csv << r + 1;
        for (unsigned int k = 0; k < sweep.values.size(); ++k)
          csv << ','
              << text_format::csv_field(
                   sweep.values[k].second[combinations[r][k]]);

        out << "  run " << r + 1 << '/' << combinations.size() << ": "
            << describe(sweep, combinations[r]) << ": ";
        if (!run_one(file,
                     run_overrides[r],
                     staging +
                       directory_of(r).substr(base.output.directory.size()),
                     directory_of(r),
                     csv,
                     out,
                     result.missed_references))
          ++result.failed_runs;
        csv << std::flush;
        if (!csv)
          throw WriteError("cannot write sweep.csv (Output/Directory '" +
                           base.output.directory + "')");
        if (interrupted())
          {
            out << "  sweep interrupted after run " << r + 1 << " of "
                << combinations.size() << std::endl;
            break;
          }
      }
    if (results)
      {
        csv_file.close();
        if (!csv_file)
          throw WriteError("cannot write sweep.csv (Output/Directory '" +
                           base.output.directory + "')");
        results->commit();
      }
    out << "  results in " << base.output.directory << "/sweep.csv"
        << std::endl;
    return result;
  }
} // namespace thinlayer
