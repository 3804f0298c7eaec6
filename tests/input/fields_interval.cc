// Truths checked: Output/Fields interval and Output/Fields of cut-back
// attempts choose which states' VTU fields a run writes. Prandtl's footing
// on its 128-cell mesh (prm/prandtl-strip-footing.prm) by Newton's method,
// bracketed to 0.5% (a run with cut-back attempts and a failure that ends
// it), four times:
// - interval 1: fields.pvd lists every accepted state of history.csv,
//   attempts.pvd the attempts that ended the run (the failure, and a probe
//   beyond it if there is one) and no cut-back attempt;
// - interval 5: fields.pvd lists the accepted states 5, 10, 15, ... and the
//   last accepted one, which is written after the failure, from the
//   accepted state: its file is byte for byte the one interval 1 wrote at
//   its step;
// - interval 0: fields.pvd lists the last accepted state alone;
// - with the cut-back attempts: attempts.pvd lists those too.
// Every file a .pvd lists exists.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  using truths::expect;

  /// The files @p directory/@p pvd lists, in order (none if it is missing).
  std::vector<std::string>
  listed(const std::string &directory, const std::string &pvd)
  {
    std::ostringstream text;
    text << std::ifstream(directory + "/" + pvd).rdbuf();
    const std::string        s = text.str();
    const std::regex         file("file=\"([^\"]+)\"");
    std::vector<std::string> files;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), file);
         it != std::sregex_iterator();
         ++it)
      files.push_back((*it)[1]);
    return files;
  }

  std::string
  fields_file(const unsigned int step)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "fields-%04u.vtu", step);
    return name;
  }

  std::string
  contents(const std::string &file)
  {
    std::ostringstream text;
    text << std::ifstream(file, std::ios::binary).rdbuf();
    return text.str();
  }

  /// The run's steps: accepted states of the curve, and the attempts that
  /// were cut back, from history.csv.
  struct Steps
  {
    std::vector<unsigned int> accepted;
    unsigned int              cut_backs      = 0;
    unsigned int              final_failures = 0;
  };

  Steps
  run(const std::string &directory,
      const std::string &interval,
      const bool         cut_backs)
  {
    std::vector<std::string> arguments = {
      std::string(SOURCE_DIR) + "/../../prm/prandtl-strip-footing.prm"};
    for (const std::string &setting : std::vector<std::string>{
           "Mesh/Geometry parameters=half_width=1, width=5, depth=3, "
           "n_footing=6, n_side=10, n_depth=8, growth=1.2",
           "Solver/Method=newton",
           "Solver/Convergence criterion=default",
           "Loading/Collapse resolution=0.005",
           "Output/Directory=" + directory,
           "Output/Fields interval=" + interval,
           std::string("Output/Fields of cut-back attempts=") +
             (cut_backs ? "true" : "false")})
      {
        arguments.push_back("-s");
        arguments.push_back(setting);
      }
    std::ostringstream out, err;
    if (thinlayer::run_command_line(arguments, out, err) != 0)
      std::printf("run failed: %s\n", err.str().c_str());
    Steps steps;
    // A cut-back attempt is followed by another at the same step; the
    // failure that ends the run (and a probe beyond it) by none.
    const auto rows     = run_results::read_csv(directory + "/history.csv");
    const auto outcomes = run_results::summary_text(directory, "outcome");
    for (unsigned int k = 0; k < rows.size(); ++k)
      {
        const auto &row = rows[k];
        if (row.at("accepted") == 1 && row.at("converged") == 1)
          steps.accepted.push_back(row.at("step"));
        else if (row.at("accepted") == 0)
          {
            if (k + 1 < rows.size() && rows[k + 1].at("step") == row.at("step"))
              ++steps.cut_backs;
            else
              ++steps.final_failures;
          }
      }
    std::printf("interval %s%s: %zu accepted states, %u cut back, %zu "
                "fields listed, %zu attempts listed; outcome %s\n",
                interval.c_str(),
                cut_backs ? " with cut-backs" : "",
                steps.accepted.size(),
                steps.cut_backs,
                listed(directory, "fields.pvd").size(),
                listed(directory, "attempts.pvd").size(),
                outcomes.c_str());
    return steps;
  }

  bool
  all_exist(const std::string &directory, const std::string &pvd)
  {
    for (const std::string &file : listed(directory, pvd))
      if (!std::filesystem::exists(directory + "/" + file))
        return false;
    return true;
  }
} // namespace


int
main()
{
  const Steps              every = run("every", "1", false);
  std::vector<std::string> expected;
  for (const unsigned int step : every.accepted)
    expected.push_back(fields_file(step));
  expect(every.cut_backs > 0 && every.accepted.size() > 6,
         "the run has cut-back attempts and more than six accepted states");
  expect(listed("every", "fields.pvd") == expected,
         "interval 1: fields.pvd lists every accepted state");
  expect(every.final_failures > 0 &&
           listed("every", "attempts.pvd").size() == every.final_failures,
         "interval 1: attempts.pvd lists the attempts that ended the run "
         "alone");

  const Steps        third = run("third", "5", false);
  const unsigned int last  = third.accepted.back();
  expected.clear();
  for (const unsigned int step : third.accepted)
    if (step % 5 == 0 || step == last)
      expected.push_back(fields_file(step));
  expect(third.accepted == every.accepted,
         "interval 5: the same steps as interval 1");
  expect(last % 5 != 0 && listed("third", "fields.pvd") == expected,
         "interval 5: fields.pvd lists the states 5, 10, 15, ... and the "
         "last (not a multiple of 5)");
  expect(contents("third/" + fields_file(last)) ==
           contents("every/" + fields_file(last)),
         "interval 5: the last state, written after the failure, is the "
         "accepted state interval 1 wrote at its step");

  run("none", "0", false);
  expect(listed("none", "fields.pvd") ==
           std::vector<std::string>{fields_file(last)},
         "interval 0: fields.pvd lists the last accepted state alone");

  const Steps studied = run("studied", "1", true);
  expect(listed("studied", "attempts.pvd").size() ==
           studied.cut_backs + studied.final_failures,
         "with the cut-back attempts: attempts.pvd lists them too");
  expect(all_exist("every", "fields.pvd") && all_exist("third", "fields.pvd") &&
           all_exist("none", "fields.pvd") &&
           all_exist("studied", "attempts.pvd"),
         "every file a .pvd lists exists");
  return truths::conclude();
}
