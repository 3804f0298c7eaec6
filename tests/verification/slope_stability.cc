// Truth checked: the safety factor of a homogeneous slope by strength
// reduction (prm/slope-strength-reduction.prm: Griffiths and Lane 1999,
// Example 1, a 2 : 1 slope on a firm base at the toe's level,
// c' / (gamma H) = 0.05, phi' = 20 degrees) against Bishop's simplified
// method of slices minimised over circles: 1.38 by Bishop and Morgenstern's
// (1960) charts, 1.378 by thinlayer_tools/limit_equilibrium.py for this
// geometry. A limit-equilibrium factor is neither a bound nor exact, but
// for a homogeneous slope it lies within about 1% of limit analysis, and
// Griffiths and Lane found strength reduction within about 2% of it:
//  - with associated flow the factor is a collapse (a plateau of F), within
//    2% of Bishop's, and it falls when the elements' size is halved (a
//    displacement method approaches the limit from above);
//  - with psi = 0 (Griffiths and Lane's) the slope stands at F within 3%
//    below Bishop's, and whatever ends the run, no collapse is claimed
//    beyond 3% above it.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// Bishop's factor, as the file's Reference/Analytic load states it
  /// (read back from the run's summary.json).
  double bishop = NAN;

  struct Result
  {
    double      factor;
    double      last_converged;
    std::string outcome;
  };


  Result
  safety(const double dilation, const unsigned int n_height)
  {
    char dilation_setting[64], mesh[200];
    std::snprintf(dilation_setting,
                  sizeof(dilation_setting),
                  "Material 1/Dilation angle=%g",
                  dilation);
    std::snprintf(mesh,
                  sizeof(mesh),
                  "Mesh/Geometry parameters=height=10, run=2, behind=20, "
                  "depth=0, n_height=%u, n_behind=%u, n_slope=%u",
                  n_height,
                  4 * n_height / 5,
                  6 * n_height / 5);
    Result r;
    r.factor = run_results::run_prm("slope-strength-reduction.prm",
                                    {dilation_setting, mesh});
    r.last_converged =
      run_results::summary_number("results", "last_converged_load");
    r.outcome = run_results::summary_text("results", "outcome");
    bishop    = run_results::summary_number("results", "reference_load");
    return r;
  }
} // namespace


int
main()
{
  using truths::expect;
  const Result coarse = safety(20, 5);
  const Result file   = safety(20, 10);
  std::printf("associated: F = %.3f (%s) on 60 cells, %.3f (%s) on 240; "
              "Bishop %.3f: %+.1f%%, %+.1f%%\n",
              coarse.factor,
              coarse.outcome.c_str(),
              file.factor,
              file.outcome.c_str(),
              bishop,
              100 * (coarse.factor / bishop - 1),
              100 * (file.factor / bishop - 1));
  expect(file.outcome == "collapse" && coarse.outcome == "collapse",
         "with associated flow the slope collapses");
  expect(std::abs(file.factor / bishop - 1) < 0.02,
         "at a factor within 2% of Bishop's");
  expect(coarse.factor > file.factor,
         "which falls when the elements' size is halved");

  const Result zero = safety(0, 10);
  std::printf("psi = 0: stands at F = %.3f (%+.1f%%), then %s\n",
              zero.last_converged,
              100 * (zero.last_converged / bishop - 1),
              zero.outcome.c_str());
  expect(zero.last_converged > 0.97 * bishop,
         "with psi = 0 the slope stands within 3% of Bishop's factor");
  expect(zero.outcome != "collapse" || zero.factor < 1.03 * bishop,
         "and no collapse is claimed beyond 3% above it");
  return truths::conclude();
}
