// ConvergenceWatch on residual histories whose fate is known. Truths checked:
// - linear convergence at rate rho from r0 is foretold exactly: the
//   iterations to reach a target t are log(t / r0) / log(rho), to 1e-9;
// - a residual that has not fallen over the window foretells no end
//   (infinite), and too short a history foretells nothing (NaN);
// - a residual that wanders for five iterations past its best before it
//   falls quadratically (a thin layer's set of yielding points settling)
//   never stagnates over Newton's window of six, and would over four;
// - a residual that stays above half its best for the window stagnates,
//   and so does one that has become NaN;
// - start() forgets the last attempt.
#include <thinlayer/solution_methods/convergence_watch.h>

#include <cmath>
#include <iostream>
#include <limits>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

int
main()
{
  ConvergenceWatch watch;

  std::cout << "* linear convergence, rate 0.8 from 1\n";
  watch.start();
  for (unsigned int k = 1; k <= 12; ++k)
    watch.add(std::pow(0.8, k));
  const double expected = std::log(1e-4) / std::log(0.8);
  expect(std::abs(watch.predicted_iterations(1e-4, 10) - expected) < 1e-9,
         "reaches 1e-4 after log(1e-4)/log(0.8) = 41.27 iterations");
  expect(std::isnan(watch.predicted_iterations(1e-4, 12)),
         "a window as long as the history foretells nothing");
  expect(!watch.stagnating(4, 0.5), "does not stagnate");

  std::cout << "* a residual that stopped falling\n";
  watch.start();
  for (unsigned int k = 0; k < 12; ++k)
    watch.add(k < 4 ? std::pow(0.5, k) : 0.125 * (1 + 0.01 * (k % 2)));
  expect(std::isinf(watch.predicted_iterations(1e-4, 2)),
         "never reaches the target (infinite)");
  expect(watch.stagnating(6, 0.5),
         "stagnates: six iterations above half the best before them");

  std::cout << "* Newton: wandering for five iterations past its best, "
               "then quadratic convergence\n";
  {
    const double residuals[] = {
      1, 0.5, 0.2, 0.1, 0.3, 0.2, 0.4, 0.15, 0.08, 6.4e-3, 4.1e-5, 1.7e-9};
    bool given_up_6 = false, given_up_4 = false;
    watch.start();
    for (const double r : residuals)
      {
        watch.add(r);
        given_up_6 = given_up_6 || watch.stagnating(6, 0.5);
        given_up_4 = given_up_4 || watch.stagnating(4, 0.5);
      }
    expect(!given_up_6,
           "a window of six (Newton's) never gives the attempt up");
    expect(given_up_4, "a window of four would have given it up");
    expect(watch.iterations() == 12, "counts its iterations");
  }

  std::cout << "* a residual that became NaN\n";
  watch.start();
  for (unsigned int k = 0; k < 6; ++k)
    watch.add(1e-2);
  for (unsigned int k = 0; k < 6; ++k)
    watch.add(std::numeric_limits<double>::quiet_NaN());
  expect(watch.stagnating(6, 0.5), "stagnates (NaN is no progress)");

  std::cout << "* start() forgets\n";
  watch.start();
  expect(watch.iterations() == 0 && !watch.stagnating(1, 0.5) &&
           std::isnan(watch.predicted_iterations(1e-4, 1)),
         "a new attempt has no history");

  return truths::conclude();
}
