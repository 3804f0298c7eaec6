// Truth checked: results never pass off overflow or failure as an answer.
// Loads so large that stresses, tractions or their invariants overflow
// (1e150 to 1e300, in cells of every yield law and in zero-thickness
// elements) end the run as `not converged` with the reason "not finite",
// exit status 0, never `completed` and never an internal error; no CSV
// field of a result is empty (a non-finite number is written nan or inf);
// a relative error against the analytic load exists only where the run
// has a collapse load or completed every step; and the row of a sweep's
// run that ended in an error has as many fields as the header, its message
// under `error`. Release only (bad_output_numbers.release.output): deal.II's
// debug library stops at the first non-finite vector norm, before the
// program can report it, as in outcome_non_finite.
#include <cmath>
#include <cstdlib>

#include "../common/bad_input_utilities.h"

using namespace bad_input;

namespace
{
  /// The fields of a CSV line (quotes as text_format::csv_field writes
  /// them).
  std::vector<std::string>
  fields(const std::string &line)
  {
    std::vector<std::string> result(1);
    bool                     quoted = false;
    for (const char c : line)
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        result.emplace_back();
      else
        result.back() += c;
    return result;
  }

  /// The rows of a CSV file as maps from the header's names.
  std::vector<std::map<std::string, std::string>>
  rows_of(const std::string &file, unsigned int &empty_fields)
  {
    std::istringstream                              in(read_text(file));
    std::string                                     line;
    std::vector<std::map<std::string, std::string>> rows;
    std::getline(in, line);
    const auto header = fields(line);
    empty_fields      = 0;
    while (std::getline(in, line))
      {
        const auto values = fields(line);
        rows.emplace_back();
        for (unsigned int k = 0; k < values.size() && k < header.size(); ++k)
          {
            rows.back()[header[k]] = values[k];
            empty_fields += values[k].empty() ? 1 : 0;
          }
        if (values.size() != header.size())
          rows.back()["(field count)"] = std::to_string(values.size()) +
                                         " fields, header " +
                                         std::to_string(header.size());
      }
    return rows;
  }

  /// Run @p arguments and print how the run ended and what its files say.
  void
  overflow(const std::string &what, std::vector<std::string> arguments)
  {
    arguments.insert(
      arguments.end(),
      {"-s", "Output/Directory=numbers", "-s", "Output/Write VTU=false"});
    std::ostringstream out, err;
    const int         status = thinlayer::run_command_line(arguments, out, err);
    unsigned int      empty  = 0;
    const auto        rows   = rows_of("numbers/history.csv", empty);
    const std::string reason = summary_entry("numbers", "reason");
    std::cout << "* " << what << "\n  exit status " << status << ", outcome "
              << summary_entry("numbers", "outcome") << ", reason "
              << reason.substr(0, reason.find(" at ")) << "\"\n  rows "
              << rows.size() << ", empty fields " << empty
              << ", last row: non_finite "
              << (rows.empty() ? "-" : rows.back().at("non_finite"))
              << ", converged "
              << (rows.empty() ? "-" : rows.back().at("converged"))
              << ", max_yield_ratio "
              << (rows.empty() ? "-" : rows.back().at("max_yield_ratio"))
              << "\n  " << err.str() << '\n';
  }

  const std::string meshes = std::string(SOURCE_DIR) + "/../../meshes/";

  void
  check_overflow()
  {
    const std::vector<std::pair<std::string, std::string>> laws = {
      {"tresca", ""},
      {"von mises", ""},
      {"mohr-coulomb", "Material 1/Friction angle=30"}};
    for (const auto &[law, extra] : laws)
      for (const char *load : {"1e200", "1e300"})
        {
          std::vector<std::string> arguments = {
            "good.prm",
            "-s",
            "Material 1/Yield criterion=" + law,
            "-s",
            "Material 1/Cohesion=1",
            "-s",
            std::string("Loading/Load increments=") + load};
          if (!extra.empty())
            arguments.insert(arguments.end(), {"-s", extra});
          overflow(std::string("a load of ") + load + " on a " + law +
                     " material",
                   arguments);
        }

    write("interface.prm",
          "subsection Mesh\n  set File = " + meshes +
            "interface-patch.geo\nend\n"
            "subsection Material 1\nend\n"
            "subsection Interface 3\n  set Slip criterion = tresca\n"
            "  set Adhesion = 1\nend\n"
            "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
            "subsection Boundary 2\n  set Traction = 1; -1\nend\n"
            "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
            "subsection Solver\n  set Maximum iterations = 40\nend\n"
            "subsection Loading\n  set Collapse resolution = 0\nend\n"
            "subsection Output\n  set Directory = results\nend\n");
    for (const char *load : {"1e10", "1e150", "1e300"})
      overflow(std::string("a load of ") + load +
                 " on zero-thickness elements (Tresca)",
               {"interface.prm",
                "-s",
                std::string("Loading/Load increments=") + load});
  }


  /// Relative errors only where there is a value to compare.
  void
  check_relative_errors()
  {
    for (const auto &[what, arguments] :
         std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"an elastic run that completed",
            {"good.prm", "-s", "Reference/Analytic load=1"}},
           {"a run that did not converge",
            {"good.prm",
             "-s",
             "Reference/Analytic load=1",
             "-s",
             "Material 1/Yield criterion=tresca",
             "-s",
             "Material 1/Cohesion=0.01",
             "-s",
             "Loading/Collapse resolution=0",
             "-s",
             "Solver/Maximum iterations=5"}}})
      {
        std::vector<std::string> all = arguments;
        all.insert(all.end(), {"-s", "Output/Directory=errors"});
        std::ostringstream out, err;
        const int          status = thinlayer::run_command_line(all, out, err);
        std::cout << "* " << what << "\n  exit status " << status
                  << ", outcome " << summary_entry("errors", "outcome")
                  << ", relative_error "
                  << summary_entry("errors", "relative_error") << ", printed: "
                  << (out.str().find("relative error") != std::string::npos
                        ? "yes"
                        : "no")
                  << "\n\n";
      }
  }


  /// A sweep whose second run ends in an error (height 0: flat cells).
  void
  check_sweep_error_row()
  {
    std::ostringstream out, err;
    const int          status =
      thinlayer::run_command_line({"good.prm",
                                   "-s",
                                   "Sweep/Values=height = 1, 0",
                                   "-s",
                                   "Output/Directory=sweep"},
                                  out,
                                  err);
    unsigned int empty = 0;
    const auto   rows  = rows_of("sweep/sweep.csv", empty);
    std::cout << "* a sweep whose second run ended in an error\n  exit status "
              << status << ", rows " << rows.size();
    for (const auto &row : rows)
      std::cout << "\n    run " << row.at("run") << ": outcome '"
                << row.at("outcome") << "', field count "
                << (row.count("(field count)") ? row.at("(field count)")
                                               : "as the header's")
                << ", error '" << row.at("error").substr(0, 60) << "'";
    std::cout << "\n\n";
  }


  /// Runs that ended with a wrong answer and exit status 0: each ends as
  /// the body does, or says why it cannot tell.
  void
  check_outcome_classes()
  {
    const std::string scenes    = std::string(SOURCE_DIR) + "/../scenes/";
    const auto        run_scene = [](const std::string              &what,
                              const std::vector<std::string> &arguments,
                              const double                    low,
                              const double                    high) {
      std::vector<std::string> all = arguments;
      all.insert(
        all.end(),
        {"-s", "Output/Directory=outcomes", "-s", "Output/Write VTU=false"});
      std::ostringstream out, err;
      const int          status = thinlayer::run_command_line(all, out, err);
      const std::string  load = summary_entry("outcomes", "collapse_load");
      char              *end  = nullptr;
      const double       read = std::strtod(load.c_str(), &end);
      const double       value = end != load.c_str() ? read : std::nan("");
      std::cout << "* " << what << "\n  exit status " << status << ", outcome "
                << summary_entry("outcomes", "outcome") << ", collapse load "
                << (std::isfinite(value)
                             ? "in [" + std::to_string(low) + ", " +
                          std::to_string(high) + "]: " +
                          (value >= low && value <= high ? "yes"
                                                                : "NO (" + load + ")")
                             : "none")
                << "\n\n";
    };
    const std::string thin = scenes + "case1_default_thin.prm";
    // Loaded to 0.49 of its collapse load, the layer's strength reduced:
    // it fails at F = 1 / 0.49 = 2.0408. The reduction's displacements
    // start at round-off, which the plateau rule must not read as growth.
    // (At half the collapse load the halvings of the reduction's steps land
    // on F = 2 exactly, the limit itself, where an equilibrium still exists
    // and whether the failed step shows a mechanism is rounding's.)
    for (const auto &[title, scene] :
         {std::pair<std::string, std::string>{
            "strength reduction of a layer loaded to 0.49 of its collapse "
            "load: F = 1 / 0.49",
            thin},
          {"the same of the 3D layer", scenes + "case1_3d_default.prm"}})
      run_scene(title,
                {scene,
                 "-s",
                 "Strength reduction/Materials=2",
                 "-s",
                 "Loading/Load increments=0.49",
                 "-s",
                 "Reference/Expected load range=0.99, 1.005",
                 "-s",
                 "Reference/Analytic load=2.0408163265306123"},
                0.99 / 0.49,
                1.005 / 0.49);
    run_scene("a first step a million times the collapse load, no state "
              "converged: no collapse load",
              {scenes + "case2_small.prm",
               "-s",
               "Loading/Load increments=1e6",
               "-s",
               "Reference/Expected outcome=not converged",
               "-s",
               "Reference/Expected load range="},
              0,
              0);
    run_scene("a strength reduction whose first step is a factor of a "
              "million: no safety factor",
              {thin,
               "-s",
               "Strength reduction/Materials=2",
               "-s",
               "Strength reduction/Factor increments=1e6",
               "-s",
               "Loading/Load increments=0.5",
               "-s",
               "Reference/Expected outcome=not converged",
               "-s",
               "Reference/Expected load range="},
              0,
              0);
    run_scene("a 3D layer of aspect ratio 1e6 loaded past its collapse: "
              "collapse within 1%",
              {scenes + "case1_3d_default.prm",
               "-s",
               "Mesh/Geometry parameters=alpha=30, aspect_ratio=1e6, "
               "elements_along=4, elements_block=2, depth=0.5, "
               "elements_depth=1"},
              0.99 * 4 / std::sqrt(3.),
              1.01 * 4 / std::sqrt(3.));
  }
} // namespace


int
main()
{
  // This test's own directories, from a run before, start empty.
  for (const char *directory : {"numbers", "errors", "sweep", "outcomes"})
    std::filesystem::remove_all(directory);
  write_valid_scene();
  check_overflow();
  check_relative_errors();
  check_sweep_error_row();
  check_outcome_classes();
}
