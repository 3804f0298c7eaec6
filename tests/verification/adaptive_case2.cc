// Truths checked on Case 2 of Griffiths (a strip footing pushed sideways;
// sliding of the footing alone needs P = L C_w) by adaptive refinement:
// - on a thin Tresca layer of aspect ratio 100
//   (prm/case2-strip-footing-adaptive.prm, the paper's coarse mesh, 10%
//   above L C_w): refined toward the mechanism (a quarter of the cells a
//   cycle), the collapse load comes within 1% of L C_w, from above, with
//   every cycle no further from it than the one before; and at no more
//   equations than the coarse mesh refined uniformly once, an adaptive
//   mesh's error is below a third of the uniform mesh's;
// - on interface elements (prm/case2-strip-footing-zero-thickness-
//   adaptive.prm, 19 cells): the first run slides at L C_w (within the
//   collapse resolution), its mechanism is the interface's slip alone, so
//   the cycles end there, with fewer equations than the scene file's own
//   mesh (prm/case2-strip-footing-zero-thickness.prm) needs for the same
//   answer.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// The cycles of prm/@p name run with @p settings.
  nlohmann::json
  cycles(const std::string &name, const std::vector<std::string> &settings)
  {
    // A run that fails leaves no summary to read.
    std::filesystem::remove_all("results");
    run_results::run_prm(name, settings);
    return run_results::summary("results")["adaptivity"];
  }


  double
  error(const nlohmann::json &cycle)
  {
    // L C_w = 1: the load factor is the collapse load over it.
    return cycle["collapse_load"].get<double>() - 1;
  }


  void
  print(const char *series, const nlohmann::json &cycle)
  {
    std::printf("%-8s cycle %u: %5u cells, %6u equations, collapse "
                "load factor %.5f, error %+.3f%%\n",
                series,
                cycle["cycle"].get<unsigned int>(),
                cycle["cells"].get<unsigned int>(),
                cycle["equations"].get<unsigned int>(),
                cycle["collapse_load"].get<double>(),
                100 * error(cycle));
  }
} // namespace


int
main()
{
  using truths::expect;

  std::printf("thin layer (aspect ratio 100)\n");
  const nlohmann::json adaptive =
    cycles("case2-strip-footing-adaptive.prm",
           {"Adaptivity/Cycles=4", "Adaptivity/Stop tolerance=0"});
  double previous = 1e9;
  for (const auto &c : adaptive["cycles"])
    {
      print("adaptive", c);
      expect(error(c) <= previous + 1e-12,
             "each adaptive cycle no further from L C_w");
      previous = error(c);
    }
  const auto &last = adaptive["cycles"].back();
  expect(error(last) >= 0 && error(last) <= 0.01,
         "the last adaptive cycle within 1% of L C_w, from above");

  const nlohmann::json uniform = cycles("case2-strip-footing-adaptive.prm",
                                        {"Adaptivity/Cycles=1",
                                         "Adaptivity/Stop tolerance=0",
                                         "Adaptivity/Marking=uniform",
                                         // Uniform marking takes no fraction:
                                         // the default, as if left out.
                                         "Adaptivity/Marking fraction=0.5"});
  const auto          &once    = uniform["cycles"].back();
  print("uniform", once);
  const nlohmann::json *match = nullptr;
  for (const auto &c : adaptive["cycles"])
    if (c["equations"].get<unsigned int>() <=
        once["equations"].get<unsigned int>())
      match = &c;
  expect(match != nullptr && error(*match) < error(once) / 3,
         "at no more equations than the uniform mesh, an adaptive mesh's "
         "error below a third of its");

  std::printf("interface elements\n");
  const nlohmann::json interface =
    cycles("case2-strip-footing-zero-thickness-adaptive.prm", {});
  expect(interface["cycles"].size() == 1, "the cycles end after the first run");
  const auto &first = interface["cycles"].front();
  print("adaptive", first);
  expect(std::abs(error(first)) <= 0.001,
         "the first run slides at L C_w (within the collapse resolution)");
  std::printf("why the cycles stopped: %s\n",
              interface["stop_reason"].get<std::string>().c_str());

  std::filesystem::remove_all("results");
  const double scene_load =
    run_results::run_prm("case2-strip-footing-zero-thickness.prm",
                         {"Loading/Collapse resolution=0.001"});
  const unsigned int scene_equations = static_cast<unsigned int>(
    run_results::summary_number("results", "equations"));
  std::printf("the scene file's mesh: %u equations, collapse load factor "
              "%.5f\n",
              scene_equations,
              scene_load);
  expect(std::abs(scene_load - 1) <= 0.001 &&
           first["equations"].get<unsigned int>() < scene_equations / 4,
         "the scene file's mesh gives the same answer with more than four "
         "times the equations");
  return truths::conclude();
}
