// What the tests that run whole scenes share: running the text of a
// parameter file, and reading back a number of a run's summary.json, and a
// CSV (history, profiles) by column name.
#ifndef thinlayer_tests_run_results_h
#define thinlayer_tests_run_results_h

#include <thinlayer/app/command_line.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>
#include <nlohmann/json.hpp>

namespace run_results
{
  /// Write @p prm to @p file and run it as the command line would, with
  /// @p options after it; what it wrote to stderr if it failed, else "".
  inline std::string
  run_text(const std::string              &prm,
           const std::vector<std::string> &options = {},
           const std::string              &file    = "scene.prm")
  {
    // On many ranks (a test under mpirun) rank 0 writes the file, and
    // every rank reads the run's results once rank 0 has written them.
    int parallel = 0;
    MPI_Initialized(&parallel);
    if (!parallel || thinlayer::mpi::is_root())
      std::ofstream(file) << prm;
    if (parallel)
      MPI_Barrier(thinlayer::mpi::communicator());
    std::vector<std::string> arguments = {file};
    arguments.insert(arguments.end(), options.begin(), options.end());
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line(arguments, out, err);
    if (parallel)
      MPI_Barrier(thinlayer::mpi::communicator());
    if (status != 0)
      return err.str().empty() ? std::string("failed\n") : err.str();
    return "";
  }

  /// The number @p key of @p directory/summary.json (NaN if it has none,
  /// or null).
  inline double
  summary_number(const std::string &directory, const std::string &key)
  {
    std::ostringstream text;
    text << std::ifstream(directory + "/summary.json").rdbuf();
    const std::string json = text.str();
    const auto        at   = json.find("\"" + key + "\": ");
    // NaN is written as null.
    return at == std::string::npos ||
               json.compare(at + key.size() + 4, 4, "null") == 0
             ? NAN
             : std::atof(json.c_str() + at + key.size() + 4);
  }

  /// The whole of @p directory/summary.json.
  inline nlohmann::json
  summary(const std::string &directory)
  {
    std::ifstream in(directory + "/summary.json");
    return nlohmann::json::parse(in);
  }

  /// The string @p key of @p directory/summary.json ("" if it has none).
  inline std::string
  summary_text(const std::string &directory, const std::string &key)
  {
    std::ostringstream text;
    text << std::ifstream(directory + "/summary.json").rdbuf();
    const std::string json = text.str();
    const auto        at   = json.find("\"" + key + "\": \"");
    if (at == std::string::npos)
      return "";
    const auto begin = at + key.size() + 5;
    return json.substr(begin, json.find('"', begin) - begin);
  }

  /// Run the command line @p arguments as the program would (printing
  /// what a failed run said), and read the number @p key of the
  /// summary.json in @p directory, where the arguments put the results.
  inline double
  run_and_read(const std::vector<std::string> &arguments,
               const std::string              &key,
               const std::string              &directory = "results")
  {
    std::ostringstream out, err;
    if (thinlayer::run_command_line(arguments, out, err) != 0)
      std::printf("run failed: %s\n", err.str().c_str());
    return summary_number(directory, key);
  }

  /// Run the project's prm/@p name with the settings @p settings (each
  /// "Section/Entry=value") into results/, without VTU files, and read the
  /// number @p key of its summary.json.
  inline double
  run_prm(const std::string              &name,
          const std::vector<std::string> &settings = {},
          const std::string              &key      = "collapse_load")
  {
    std::vector<std::string> arguments = {std::string(SOURCE_DIR) +
                                            "/../../prm/" + name,
                                          "-s",
                                          "Output/Directory=results",
                                          "-s",
                                          "Output/Write VTU=false"};
    for (const std::string &setting : settings)
      {
        arguments.push_back("-s");
        arguments.push_back(setting);
      }
    return run_and_read(arguments, key);
  }

  /// The Monitors and Output sections of a scene a test writes: the
  /// reaction of boundary 1 along y against the displacement of boundary 3
  /// along y, into results/, without VTU files.
  inline std::string
  reaction_monitors_and_output()
  {
    return "subsection Monitors\n  set Load measure = reaction\n"
           "  set Load boundary id = 1\n  set Load component = y\n"
           "  set Displacement boundary id = 3\n"
           "  set Displacement component = y\nend\n"
           "subsection Output\n  set Directory = results\n"
           "  set Write VTU = false\nend\n";
  }

  using Table = std::vector<std::map<std::string, double>>;

  /// A CSV of numbers, row by row, by column name.
  inline Table
  read_csv(const std::string &file)
  {
    std::ifstream            in(file);
    std::string              line;
    std::vector<std::string> names;
    Table                    rows;
    std::getline(in, line);
    std::istringstream header(line);
    for (std::string name; std::getline(header, name, ',');)
      names.push_back(name);
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        rows.emplace_back();
        std::string value;
        for (const std::string &name : names)
          if (std::getline(row, value, ','))
            rows.back()[name] = std::atof(value.c_str());
      }
    return rows;
  }

  /// Of the column @p field of a profile's @p rows, in order along the
  /// interface: the largest magnitude, and the largest difference between
  /// neighbouring rows (an empty profile: infinity, 0).
  inline std::pair<double, double>
  spread(const Table &rows, const std::string &field)
  {
    double largest = rows.empty() ? 1e300 : 0, jump = 0;
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        largest = std::max(largest, std::abs(rows[k].at(field)));
        if (k > 0)
          jump =
            std::max(jump, std::abs(rows[k].at(field) - rows[k - 1].at(field)));
      }
    return {largest, jump};
  }

  /// The newest of the files @p directory/@p prefix NNNN.csv (the last
  /// step's profile), its name; empty where there is none.
  inline std::string
  newest_csv(const std::string &directory, const std::string &prefix)
  {
    std::string last;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      {
        // PREFIX then the step's digits alone: "interface-4-" is not
        // "interface-4-gauss-".
        const std::string name = entry.path().filename().string();
        const std::string step =
          name.size() > prefix.size() + 4
            ? name.substr(prefix.size(), name.size() - prefix.size() - 4)
            : "";
        if (name.rfind(prefix, 0) == 0 && entry.path().extension() == ".csv" &&
            !step.empty() &&
            step.find_first_not_of("0123456789") == std::string::npos)
          last = std::max(last, name);
      }
    return last.empty() ? last : directory + "/" + last;
  }

} // namespace run_results

#endif
