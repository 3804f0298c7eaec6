// Truths checked for the parts of a load step cut back (SubStepping),
// against made-up bodies whose parts converge up to a known length:
// 1. Step 0 -> 1, parts up to 0.3 converge, 4 cut-backs allowed: attempts
//    at 1 and 0.5 fail, 0.25 converges, then 0.5, 0.75 and 1 (the end
//    itself): 2 cut-backs, done.
// 2. The same with 1 cut-back: 1 and 0.5 fail, and the step has failed.
// 3. Step 0 -> 0.3 in parts up to 0.1: the last part's target is exactly
//    0.3, not a sum of parts that rounds near it.
// 4. A step that converges at once is attempted once, at its end.
#include <thinlayer/solution_methods/sub_stepping.h>

#include <cstdio>
#include <iostream>
#include <vector>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  /// The targets attempted from @p start to @p end, parts converging up to
  /// @p longest; whether the step converged, and its cut-backs.
  std::vector<double>
  walk(const double       start,
       const double       end,
       const unsigned int max_cut_backs,
       const double       longest,
       bool              &converged,
       unsigned int      &cut_backs)
  {
    SubStepping         parts(start, end, max_cut_backs);
    std::vector<double> targets;
    double              accepted = start;
    while (true)
      {
        const double target = parts.target();
        targets.push_back(target);
        const auto next = parts.report(target - accepted <= longest + 1e-15);
        std::printf(" %.6g", target);
        if (next == SubStepping::Next::next_part)
          accepted = target;
        if (next == SubStepping::Next::done ||
            next == SubStepping::Next::failed)
          {
            converged = (next == SubStepping::Next::done);
            break;
          }
      }
    cut_backs = parts.cut_backs();
    std::printf(": %s, %u cut-backs\n",
                converged ? "converged" : "failed",
                cut_backs);
    return targets;
  }
} // namespace


int
main()
{
  bool         converged;
  unsigned int cut_backs;

  std::cout << "1. Cut back twice\n ";
  auto t = walk(0, 1, 4, 0.3, converged, cut_backs);
  expect(t == std::vector<double>{1, 0.5, 0.25, 0.5, 0.75, 1} && converged &&
           cut_backs == 2,
         "1, 0.5 fail; 0.25, 0.5, 0.75, 1 converge");

  std::cout << "2. One cut-back allowed\n ";
  t = walk(0, 1, 1, 0.3, converged, cut_backs);
  expect(t == std::vector<double>{1, 0.5} && !converged && cut_backs == 1,
         "1, 0.5 fail: the step failed");

  std::cout << "3. The end exactly\n ";
  t = walk(0, 0.3, 3, 0.1, converged, cut_backs);
  expect(converged && t.back() == 0.3, "the last target is 0.3 itself");

  std::cout << "4. At once\n ";
  t = walk(0.2, 0.7, 3, 1, converged, cut_backs);
  expect(t == std::vector<double>{0.7} && converged && cut_backs == 0,
         "one attempt, at 0.7");
  return truths::conclude();
}
