// Truths checked on the rough rigid circular footing in 3D
// (prm/circular-footing-rigid-3d.prm on a coarse quarter mesh, weightless
// Tresca soil, displacement control), where a factorisation of the tangent
// costs many tens of substitutions. Solver/Maximum iterations = 40 caps the
// accelerated method's budget below what some early plastic steps need, so
// that Newton has to take those. The default method
// (accelerated with newton fallback) then goes back to its cheap iterations
// for the steps they can take, rather than turning to Newton for good:
// - Newton converged at least one of its steps (a step with
//   factorisations), and at least one later step was converged with none;
// - it factorised no more than half as often as Newton alone
//   (Solver/Method = newton);
// - both accept states at the same load factors (displacements), and the
//   load of each is within 0.5% (the collapse resolution) of Newton's: the
//   path the budget chooses does not move the answer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  struct Run
  {
    double             last_load;
    std::string        outcome;
    unsigned int       factorisations;
    run_results::Table history;
  };

  Run
  run(const std::string &method)
  {
    const double last_load = run_results::run_prm(
      "circular-footing-rigid-3d.prm",
      {"Mesh/Geometry parameters=sector=90, footing=0, half_width=1, "
       "width=5, depth=3, n_around=2, n_footing=2, n_side=6, n_depth=6, "
       "growth=1.3",
       "Solver/Method=" + method,
       "Solver/Newton corrections=factorised",
       "Solver/Maximum iterations=40"},
      "last_converged_load");
    return {last_load,
            run_results::summary_text("results", "outcome"),
            static_cast<unsigned int>(
              run_results::summary_number("results", "factorisations")),
            run_results::read_csv("results/history.csv")};
  }
} // namespace


int
main()
{
  using truths::expect;
  const Run fallback = run("accelerated with newton fallback");
  const Run newton   = run("newton");

  // The accepted steps, in order.
  int  first_newton_step = -1;
  bool cheap_after       = false;
  for (std::size_t k = 0; k < fallback.history.size(); ++k)
    {
      const auto &row = fallback.history[k];
      if (row.at("accepted") != 1)
        continue;
      if (row.at("factorisations") > 0 && first_newton_step < 0)
        first_newton_step = k;
      else if (first_newton_step >= 0 && row.at("factorisations") == 0)
        cheap_after = true;
    }
  // Each accepted state against Newton's at the same load factor: the
  // failed attempts of the two runs differ, their accepted states may not.
  std::map<double, double> newton_loads;
  for (const auto &row : newton.history)
    if (row.at("accepted") == 1)
      newton_loads[row.at("load_factor")] = row.at("load");
  double       largest_difference = 0;
  unsigned int compared = 0, accepted = 0;
  for (const auto &row : fallback.history)
    if (row.at("accepted") == 1)
      {
        ++accepted;
        const auto at = newton_loads.find(row.at("load_factor"));
        if (at == newton_loads.end())
          continue;
        ++compared;
        largest_difference =
          std::max(largest_difference,
                   std::abs(row.at("load") / at->second - 1));
      }
  std::printf("default method: %s, last load %.4f c, %u factorisations; "
              "Newton: %s, %.4f c, %u factorisations\n",
              fallback.outcome.c_str(),
              fallback.last_load,
              fallback.factorisations,
              newton.outcome.c_str(),
              newton.last_load,
              newton.factorisations);
  expect(first_newton_step >= 0, "Newton converged a step of the default");
  expect(cheap_after,
         "a later step converged without a factorisation (the cheap method)");
  expect(2 * fallback.factorisations <= newton.factorisations,
         "the default factorised at most half as often as Newton");
  expect(compared == accepted && accepted == newton_loads.size() &&
           largest_difference <= 0.005,
         "the same accepted load factors, every step's load within 0.5% of "
         "Newton's");
  return truths::conclude();
}
