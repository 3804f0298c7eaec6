// GrowthMonitor on prescribed iteration histories of a step's displacement
// increment. The change is measured from the first iteration, at N/2 and
// at N. Truths checked: a step creeping along a mechanism (the increment
// growing by the same amount every iteration) gives (N - 1)/(N/2 - 1), 2 in
// the limit, to round-off; one converging geometrically at rate rho gives
// (1 - rho^(N-1))/(1 - rho^(N/2-1)), about 1 + rho^(N/2); a step that stops
// before half its limit gives NaN; and the largest change over several
// modes is the one measured.
#include <thinlayer/solution_methods/growth_monitor.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  /// The growth ratio after @p iterations of at most @p limit, the
  /// increment of iteration k being @p increment(k) times a fixed vector
  /// in the modes that @p moving names.
  template <typename Increment>
  double
  ratio(const unsigned int       iterations,
        const unsigned int       limit,
        const Increment         &increment,
        const std::vector<bool> &moving = {true})
  {
    ModeVectors   m(moving.size(), ModeVector(3));
    GrowthMonitor monitor;
    for (unsigned int k = 1; k <= iterations; ++k)
      {
        for (unsigned int i = 0; i < moving.size(); ++i)
          if (moving[i])
            for (unsigned int j = 0; j < 3; ++j)
              m[i][j] = (j + 1.) * increment(k) * (i + 1);
        monitor.iteration_done(k, limit, m);
      }
    return monitor.growth_ratio(m);
  }
} // namespace


int
main()
{
  std::cout << "* creep along a mechanism: du_k = k\n";
  {
    const double r = ratio(250, 250, [](const unsigned int k) { return k; });
    std::printf("  growth ratio %.15g, (N - 1)/(N/2 - 1) %.15g\n",
                r,
                249. / 124.);
    expect(std::abs(r - 249. / 124.) < 1e-14, "the closed form");
  }

  std::cout << "* geometric convergence: du_k = sum_{j<k} rho^j\n";
  for (const double rho : {0.9, 0.97, 0.99})
    {
      const unsigned int N = 100;
      const double       r = ratio(N, N, [rho](const unsigned int k) {
        return (1 - std::pow(rho, k)) / (1 - rho);
      });
      // The change since iteration 1 at k is rho (1 - rho^(k-1))/(1 - rho):
      // at N against N/2, (1 - rho^(N-1)) / (1 - rho^(N/2-1)).
      const double exact =
        (1 - std::pow(rho, N - 1)) / (1 - std::pow(rho, N / 2 - 1));
      std::printf("  rho %.2f: growth ratio %.12f, closed form %.12f, "
                  "1 + rho^(N/2) %.6f\n",
                  rho,
                  r,
                  exact,
                  1 + std::pow(rho, N / 2));
      expect(std::abs(r - exact) < 1e-12 * exact, "the closed form");
    }

  std::cout << "* a step that stops early\n";
  {
    const double r = ratio(40, 100, [](const unsigned int k) { return k; });
    expect(std::isnan(r), "no ratio before half the limit");
  }

  std::cout << "* two modes, only the second creeping\n";
  {
    const double r =
      ratio(200, 200, [](const unsigned int k) { return k; }, {false, true});
    std::printf("  growth ratio %.15g\n", r);
    expect(std::abs(r - 199. / 99.) < 1e-14, "the creeping mode is measured");
  }

  return truths::conclude();
}
