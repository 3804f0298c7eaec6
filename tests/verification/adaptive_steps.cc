// Truths checked on Prandtl's smooth flexible strip footing (weightless
// Tresca soil, prm/prandtl-strip-footing.prm on its coarsest benchmark
// mesh, 128 cells) by the default solution method, on the file's
// programme of short steps near the collapse (0.5, 3*0.1, 20*0.01,
// 10*0.02), once as given (Loading/Step length = programme) and once with
// adaptive step lengths:
// - both end in a collapse bracketed to the collapse resolution (0.5%),
//   and the two brackets overlap: the adaptive steps find the same
//   collapse load factor;
// - both brackets lie within 1% of Prandtl's (2 + pi) c (the mesh's error
//   at this size);
// - the adaptive steps take fewer attempts and fewer iterations.
#include <cstdio>
#include <string>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  struct Run
  {
    std::string  outcome;
    double       low;
    double       high;
    unsigned int attempts;
    unsigned int iterations;
  };

  Run
  run(const std::string &step_length)
  {
    run_results::run_prm(
      "prandtl-strip-footing.prm",
      {"Mesh/Geometry parameters=half_width=1, width=5, depth=3, "
       "n_footing=6, n_side=10, n_depth=8, growth=1.2",
       "Solver/Method=accelerated with newton fallback",
       "Solver/Convergence criterion=default",
       "Loading/Step length=" + step_length});
    const auto summary = run_results::summary("results");
    const auto bracket = summary["collapse_load_factor_bracket"];
    return {summary["outcome"],
            bracket.value("low", 0.),
            bracket.value("high", 0.),
            summary["attempts"],
            summary["total_iterations"]};
  }
} // namespace


int
main()
{
  using truths::expect;
  const Run given    = run("programme");
  const Run adaptive = run("adaptive");
  for (const auto &[name, r] : {std::make_pair("programme", given),
                                std::make_pair("adaptive", adaptive)})
    std::printf("%s: %s, load factor bracket [%.5f, %.5f], %u attempts, "
                "%u iterations\n",
                name,
                r.outcome.c_str(),
                r.low,
                r.high,
                r.attempts,
                r.iterations);
  for (const Run &r : {given, adaptive})
    expect(r.outcome == "collapse" && r.high > r.low &&
             r.high - r.low <= 0.005 * r.high * (1 + 1e-9),
           "a collapse bracketed to 0.5%");
  expect(adaptive.low < given.high && given.low < adaptive.high,
         "the brackets overlap");
  expect(given.low >= 0.99 && given.high <= 1.01 && adaptive.low >= 0.99 &&
           adaptive.high <= 1.01,
         "both within 1% of (2 + pi) c");
  expect(adaptive.attempts < given.attempts &&
           adaptive.iterations < given.iterations,
         "adaptive steps: fewer attempts and fewer iterations");
  return truths::conclude();
}
