// Truth checked: further loading phases (Phase <n>) hold what the phases
// before them reached and apply their own boundary values from there.
//  - An elastic oedometric column (E = 1e4, nu = 0.3, height H = 2, width
//    W = 1, base fixed, sides on rollers) whose top is pushed down by
//    1e-3 (the Loading section), 2e-3 further (Phase 2, two steps) and
//    back up by 3e-3 (Phase 3): at the end of each phase the base carries
//    M u W / H (M the constrained modulus, u the top's settlement so far:
//    1e-3, 3e-3, 0), to 1e-9 of the largest (history.csv's ten digits);
//    history.csv names the phases, and summary.json lists each with its
//    own outcome (completed) and its own end (its final displacement).
//  - A block pressed down by V (the Loading section) and pushed sideways
//    (Phase 2, V held) on zero-thickness Coulomb interface elements
//    (prm/sliding-block.prm): its horizontal force levels off at
//    H = V tan(delta) (Coulomb's law of sliding friction, exact for a
//    rigid block whatever the distribution of the normal tractions), to
//    1e-9, for delta = 20 and 30 degrees; in summary.json's list of the
//    phases that plateau is the push's, and the loading has none. The
//    statics hold to the equilibrium the iterations reach: the block's
//    runs converge to TOL = 1e-10, so that the truth measures the law of
//    friction rather than where an inexact Newton method stopped (at the
//    file's 1e-4 it holds to 4e-8).
#include <thinlayer/app/command_line.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  const double E = 1e4, nu = 0.3, height = 2;

  std::string
  column()
  {
    return "subsection Mesh\n  set File = " + std::string(SOURCE_DIR) +
           "/../../meshes/block.geo\n  set Geometry parameters = width=1, "
           "height=2, nx=2, ny=4\nend\n"
           "subsection Material 1\n  set Young's modulus = 1e4\n"
           "  set Poisson's ratio = 0.3\nend\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Constrained components = x\nend\n"
           "subsection Boundary 3\n  set Constrained components = y\n"
           "  set Displacement = 0; -1e-3\nend\n"
           "subsection Boundary 4\n  set Constrained components = x\nend\n"
           "subsection Loading\n  set Load increments = 1\nend\n"
           "subsection Phase 2\n  set Name = further\n"
           "  set Load increments = 0.5, 0.5\n"
           "  subsection Boundary 3\n    set Displacement = 0; -2e-3\n  end\n"
           "end\n"
           "subsection Phase 3\n  set Name = back\n"
           "  set Load increments = 1\n"
           "  subsection Boundary 3\n    set Displacement = 0; 3e-3\n  end\n"
           "end\n" +
           run_results::reaction_monitors_and_output();
  }


  /// The entries of results/summary.json's list of phases, each as its
  /// text.
  std::vector<std::string>
  listed_phases()
  {
    std::ifstream            in("results/summary.json");
    const std::string        json((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    std::vector<std::string> entries;
    const auto               begin = json.find("\"phases\": [");
    const auto               end   = json.find("\n  ]", begin);
    if (begin == std::string::npos || end == std::string::npos)
      return entries;
    for (auto at = json.find('{', begin); at != std::string::npos && at < end;
         at      = json.find('{', at + 1))
      entries.push_back(json.substr(at, json.find('}', at) - at));
    return entries;
  }


  /// Whether the phase entry @p entry has the member @p text.
  bool
  has(const std::string &entry, const std::string &text)
  {
    return entry.find(text) != std::string::npos;
  }


  /// The number @p key of the phase entry @p entry (NaN if null or none).
  double
  number(const std::string &entry, const std::string &key)
  {
    const auto at = entry.find("\"" + key + "\": ");
    return at == std::string::npos ||
               entry.compare(at + key.size() + 4, 4, "null") == 0
             ? NAN
             : std::atof(entry.c_str() + at + key.size() + 4);
  }


  /// The last accepted row of each phase of results/history.csv: (phase,
  /// load, displacement).
  std::vector<std::tuple<std::string, double, double>>
  phase_ends()
  {
    std::ifstream in("results/history.csv");
    std::string   line;
    std::getline(in, line);
    std::vector<std::tuple<std::string, double, double>> ends;
    while (std::getline(in, line))
      {
        std::vector<std::string> cells;
        std::string              cell;
        for (std::istringstream s(line); std::getline(s, cell, ',');)
          cells.push_back(cell);
        const std::string phase = cells.back();
        if (cells.size() < 10 || cells[9] != "1")
          continue;
        if (ends.empty() || std::get<0>(ends.back()) != phase)
          ends.emplace_back(phase, 0., 0.);
        ends.back() = {phase, std::stod(cells[3]), std::stod(cells[4])};
      }
    return ends;
  }
} // namespace


int
main()
{
  using truths::expect;
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));

  std::string failure = run_results::run_text(column());
  expect(failure.empty(), "the column runs" + failure);
  const auto   ends      = phase_ends();
  const double settled[] = {1e-3, 3e-3, 0};
  const char  *names[]   = {"loading", "further", "back"};
  expect(ends.size() == 3, "history.csv has three phases");
  double worst = 0;
  for (unsigned int k = 0; k < ends.size() && k < 3; ++k)
    {
      const auto [phase, load, displacement] = ends[k];
      const double exact                     = M * settled[k] / height;
      std::printf("%-8s top moved %+.6e (exact %+.6e), base carries %.10g "
                  "(M u W / H = %.10g)\n",
                  phase.c_str(),
                  displacement,
                  -settled[k],
                  std::abs(load),
                  exact);
      expect(phase == names[k], "the phase is named " + std::string(names[k]));
      worst = std::max({worst,
                        std::abs(std::abs(load) - exact) / (M * 3e-3 / height),
                        std::abs(displacement + settled[k]) / 3e-3});
    }
  expect(worst < 1e-9, "each phase starts where the one before it ended");
  const auto listed = listed_phases();
  bool       each   = listed.size() == 3;
  for (unsigned int k = 0; each && k < 3; ++k)
    each =
      has(listed[k], "\"name\": \"" + std::string(names[k]) + "\"") &&
      has(listed[k], "\"outcome\": \"completed\"") &&
      std::abs(number(listed[k], "final_displacement") + settled[k]) < 1e-12;
  std::printf("summary.json lists %zu phases\n", listed.size());
  expect(each,
         "summary.json lists the three phases, each completed, each "
         "ending where it moved the top");

  for (const double delta : {20., 30.})
    {
      char scale[32];
      std::snprintf(scale,
                    sizeof(scale),
                    "%.17g",
                    1 / (10 * std::tan(delta * M_PI / 180)));
      std::vector<std::string> arguments = {
        std::string(SOURCE_DIR) + "/../../prm/sliding-block.prm",
        "-s",
        "Interface 4/Friction angle=" + std::to_string(delta),
        "-s",
        "Monitors/Load scale=" + std::string(scale),
        "-s",
        "Output/Directory=results",
        "-s",
        "Output/Write VTU=false",
        "-s",
        "Solver/Tolerance=1e-10"};
      std::ostringstream out, err;
      const int    status = thinlayer::run_command_line(arguments, out, err);
      const double h = run_results::summary_number("results", "collapse_load");
      std::printf("sliding block, delta = %.0f: H / (V tan(delta)) = %s\n",
                  delta,
                  std::abs(h - 1) < 1e-9 ? "1 to 1e-9" : "NOT 1");
      expect(status == 0, "the block's run succeeds" + err.str());
      expect(std::abs(h - 1) < 1e-9, "H = V tan(delta)");
      std::ifstream in("results/history.csv");
      std::string   text((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
      expect(text.find(",loading\n") != std::string::npos &&
               text.find(",push\n") != std::string::npos,
             "history.csv names the loading and the push");
      const auto phases = listed_phases();
      expect(phases.size() == 2 &&
               std::isnan(number(phases[0], "collapse_load")) &&
               std::abs(number(phases[1], "collapse_load") - 1) < 1e-9 &&
               has(phases[1], "\"name\": \"push\""),
             "the plateau is the push's, the loading has none");
    }
  return truths::conclude();
}
