// Truths checked on Prandtl's smooth flexible strip footing (weightless
// Tresca soil, q_ult = (2 + pi) c), prm/prandtl-strip-footing-adaptive.prm
// from a uniform coarse mesh of 72 cells, the collapse bracketed to 0.1%:
// - refined toward the mechanism (bulk marking of 0.6 of the plastic
//   work, 3 cycles), the collapse load comes within 0.3% of (2 + pi) c,
//   from above (a displacement element's collapse load is an upper
//   bound's kind: it overestimates on a coarse mesh), and every cycle's is
//   no further from it than the one before;
// - the uniform refinement of the same mesh needs more equations than the
//   adaptive mesh for the same error: its first mesh within the adaptive
//   error has more equations than the last adaptive mesh;
// - the cycles are recorded: adaptivity.csv and summary.json's
//   "adaptivity" list the same cycles, each cycle's run in cycle-N.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  const double prandtl = 2 + M_PI;

  nlohmann::json
  run(const std::string &marking, const unsigned int cycles)
  {
    std::vector<std::string> settings = {
      "Mesh/Geometry parameters=half_width=1, width=5, depth=3, "
      "n_footing=4, n_side=8, n_depth=6, growth=1",
      "Loading/Collapse resolution=0.001",
      "Adaptivity/Cycles=" + std::to_string(cycles),
      "Adaptivity/Marking=" + marking,
      "Adaptivity/Stop tolerance=0"};
    // Uniform marking takes no fraction: the file's set back to the
    // default, as if left out.
    settings.push_back(std::string("Adaptivity/Marking fraction=") +
                       (marking == "bulk" ? "0.6" : "0.5"));
    // A run that fails leaves no summary to read.
    std::filesystem::remove_all("results");
    run_results::run_prm("prandtl-strip-footing-adaptive.prm", settings);
    return run_results::summary("results")["adaptivity"];
  }
} // namespace


int
main()
{
  using truths::expect;
  const nlohmann::json adaptive = run("bulk", 3);
  const auto           csv = run_results::read_csv("results/adaptivity.csv");
  expect(csv.size() == adaptive["cycles"].size() &&
           adaptive["cycles"].size() == 4,
         "adaptivity.csv and summary.json list the 4 cycles");
  for (unsigned int c = 0; c < adaptive["cycles"].size(); ++c)
    expect(std::filesystem::exists("results/cycle-" + std::to_string(c) +
                                   "/history.csv"),
           "cycle " + std::to_string(c) + "'s run is in cycle-" +
             std::to_string(c));
  const nlohmann::json uniform = run("uniform", 2);

  double previous = 1e9;
  for (const auto &[name, series] : {std::make_pair("adaptive", adaptive),
                                     std::make_pair("uniform", uniform)})
    for (const auto &c : series["cycles"])
      {
        const double error = c["collapse_load"].get<double>() / prandtl - 1;
        std::printf("%-8s cycle %u: %5u cells, %6u equations, collapse "
                    "load %.4f, error %+.3f%%\n",
                    name,
                    c["cycle"].get<unsigned int>(),
                    c["cells"].get<unsigned int>(),
                    c["equations"].get<unsigned int>(),
                    c["collapse_load"].get<double>(),
                    100 * error);
        if (name == std::string("adaptive"))
          {
            expect(error <= previous + 1e-9,
                   "each adaptive cycle no further from (2 + pi) c");
            previous = error;
          }
      }
  const auto  &last       = adaptive["cycles"].back();
  const double last_error = last["collapse_load"].get<double>() / prandtl - 1;
  expect(last_error >= 0 && last_error <= 0.003,
         "the last adaptive cycle within 0.3% of (2 + pi) c, from above");
  unsigned int uniform_equations = 0;
  for (const auto &c : uniform["cycles"])
    if (c["collapse_load"].get<double>() / prandtl - 1 <= last_error + 1e-9)
      {
        uniform_equations = c["equations"].get<unsigned int>();
        break;
      }
  std::printf("equations for the adaptive error: adaptive %u, uniform %u\n",
              last["equations"].get<unsigned int>(),
              uniform_equations);
  expect(uniform_equations > last["equations"].get<unsigned int>(),
         "the uniform refinement needs more equations for the same error");
  return truths::conclude();
}
