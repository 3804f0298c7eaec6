// Truth checked: extrapolate_collapse_load() recovers P_inf and the rate of
// P = P_inf + C N^(-rate) from the last three cycles with a collapse load:
// exactly (to 1e-9) for loads made by that law, from above (C > 0) and
// from below (C < 0), on DoFs that do not grow by a constant factor, with
// a cycle without a collapse load among them skipped; and not at all
// (NaN) where the loads show no such rate: changes of both signs, a change
// that grows, or fewer than three loads.
#include <thinlayer/app/adaptive_run.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "../common/truths.h"

namespace
{
  std::vector<thinlayer::CycleSummary>
  cycles(const std::vector<std::pair<unsigned int, double>> &points)
  {
    std::vector<thinlayer::CycleSummary> result;
    for (const auto &[dofs, load] : points)
      {
        thinlayer::CycleSummary c;
        c.cycle         = result.size();
        c.dofs          = dofs;
        c.collapse_load = load;
        result.push_back(c);
      }
    return result;
  }

  double
  law(const double p_inf, const double c, const double rate, const double n)
  {
    return p_inf + c * std::pow(n, -rate);
  }
} // namespace


int
main()
{
  using truths::expect;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double c : {3.0, -2.0})
    {
      const auto [p, rate] = thinlayer::extrapolate_collapse_load(
        cycles({{150, law(5.1416, c, 0.8, 150)},
                {300, nan},
                {420, law(5.1416, c, 0.8, 420)},
                {1500, law(5.1416, c, 0.8, 1500)},
                {5100, law(5.1416, c, 0.8, 5100)}}));
      std::printf("C = %+.0f: P_inf %.10f, rate %.10f\n", c, p, rate);
      expect(std::abs(p - 5.1416) < 1e-9 && std::abs(rate - 0.8) < 1e-9,
             "P_inf and the rate recovered");
    }
  const auto none = [](const std::vector<std::pair<unsigned int, double>> &x) {
    const auto [p, rate] = thinlayer::extrapolate_collapse_load(cycles(x));
    return std::isnan(p) && std::isnan(rate);
  };
  expect(none({{100, 5.3}, {400, 5.2}, {1600, 5.25}}),
         "no rate where the changes have both signs");
  expect(none({{100, 5.3}, {400, 5.29}, {1600, 5.2}}),
         "no rate where the change grows");
  expect(none({{100, 5.3}, {400, 5.2}}), "no rate from two loads");
  return truths::conclude();
}
