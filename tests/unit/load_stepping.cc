// LoadStepping against a body whose collapse load factor is known: a step
// converges exactly when its target lies at or below the limit. Truths
// checked:
// - automatic stepping brackets the limit between the last accepted load
//   factor and the last failed target, at most the collapse resolution r
//   times the target apart, with the limit inside the bracket; and it
//   halves a failed step (the attempts after a failure at 1 are 0.9 + 0.05,
//   0.9 + 0.025, ...);
// - a cut step grows back by doubling after an easy step only, up to the
//   programme's own;
// - with r = 0 the programme is run as given and the first failure ends it;
//   with Solver/Continue after failure it is accepted and the programme
//   goes on;
// - a non-finite result ends the run at once, whatever r;
// - a programme without failures attempts exactly its own load factors;
// - Step length = adaptive: a limit is bracketed as with the programme, in
//   fewer attempts than a programme of short steps near it; a load factor
//   that failed is never passed before a state there converged; a
//   failure that came of a step too long is passed (the run ends at the
//   programme's end); steps grow past the programme's increments after
//   easy steps and shrink after ones near the iteration budget;
// - failure_is_final() says beforehand, at every attempt, whether a failure
//   there is kept (ends the run, or is accepted and the programme goes on)
//   rather than cut back: what the solution method is told, so that it runs
//   such an attempt to its iteration limit.
#include <thinlayer/stepping/load_stepping.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <vector>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  /// Failed attempts whose end failure_is_final() did not foretell.
  unsigned int final_mispredicted = 0;

  StepResult
  result(const bool converged, const unsigned int iterations)
  {
    StepResult r;
    r.iterations      = iterations;
    r.converged       = converged;
    r.max_yield_ratio = 0;
    r.plastic_points  = 0;
    return r;
  }


  LoadingParameters
  programme(const std::vector<double> &increments,
            const double               resolution,
            const bool                 adaptive = false)
  {
    LoadingParameters loading;
    loading.load_increments     = increments;
    loading.collapse_resolution = resolution;
    loading.step_length = adaptive ? LoadingParameters::StepLength::adaptive
                                   : LoadingParameters::StepLength::programme;
    return loading;
  }


  /// Prandtl's file programme: 0.5, 3*0.1, 20*0.01, 10*0.02.
  std::vector<double>
  prandtl_programme()
  {
    std::vector<double> increments{0.5, 0.1, 0.1, 0.1};
    increments.insert(increments.end(), 20, 0.01);
    increments.insert(increments.end(), 10, 0.02);
    return increments;
  }


  /// Attempts of @p stepping against a body whose steps converge up to
  /// @p limit, and only where no longer than @p longest, in @p iterations
  /// each; whether an attempt went past a load factor that had failed
  /// before any state there converged. Returns the last accepted load
  /// factor and the last target.
  struct Walk
  {
    double       low;
    double       high;
    unsigned int attempts;
    bool         passed_a_failure;
    double       longest_step;
  };

  Walk
  walk(LoadStepping      &stepping,
       const double       limit,
       const double       longest,
       const unsigned int iterations)
  {
    Walk                walked{0, 0, 0, false, 0};
    std::vector<double> failed; // not yet reached by a converged state
    while (!stepping.finished())
      {
        const double target = stepping.target();
        for (const double f : failed)
          if (target > f * (1 + 1e-14))
            walked.passed_a_failure = true;
        const bool converged = target <= limit * (1 + 1e-14) &&
                               target - walked.low <= longest * (1 + 1e-14);
        const bool final = stepping.failure_is_final();
        const auto next  = stepping.report(result(converged, iterations));
        if (!converged && (next != LoadStepping::Next::retry) != final)
          ++final_mispredicted;
        ++walked.attempts;
        walked.high = target;
        if (next == LoadStepping::Next::stop)
          break;
        if (converged)
          {
            walked.longest_step =
              std::max(walked.longest_step, target - walked.low);
            walked.low = target;
            std::vector<double> left;
            for (const double f : failed)
              if (f > target * (1 + 1e-14))
                left.push_back(f);
            failed = left;
          }
        else
          failed.push_back(target);
      }
    return walked;
  }


  void
  stepping_report_converged(LoadStepping      &stepping,
                            const unsigned int iterations)
  {
    stepping.report(result(true, iterations));
  }


  /// Runs the stepping against a body whose steps converge up to @p limit
  /// in @p iterations each; prints every attempt. Returns the last accepted
  /// load factor and the last target (the failed one, or the end).
  std::pair<double, double>
  run(LoadStepping      &stepping,
      const double       limit,
      const unsigned int iterations,
      const bool         print = true)
  {
    double accepted = 0, target = 0;
    while (!stepping.finished())
      {
        target               = stepping.target();
        const bool converged = target <= limit * (1 + 1e-14);
        const bool final     = stepping.failure_is_final();
        const auto next      = stepping.report(result(converged, iterations));
        if (!converged && (next != LoadStepping::Next::retry) != final)
          ++final_mispredicted;
        if (print)
          std::printf("    attempt at %.6g: %s\n",
                      target,
                      next == LoadStepping::Next::accept  ? "accept"
                      : next == LoadStepping::Next::retry ? "retry"
                      : next == LoadStepping::Next::accept_failed
                        ? "accept failed"
                        : "stop");
        if (next == LoadStepping::Next::accept ||
            next == LoadStepping::Next::accept_failed)
          accepted = target;
        if (next == LoadStepping::Next::stop)
          break;
      }
    return {accepted, target};
  }
} // namespace


int
main()
{
  std::cout << "* automatic stepping, limit 0.93, programme 0.5, 5*0.1, "
               "r = 0.005\n";
  {
    LoadStepping stepping(programme({0.5, 0.1, 0.1, 0.1, 0.1, 0.1}, 0.005),
                          false,
                          10);
    const auto [low, high] = run(stepping, 0.93, 3);
    std::printf("  bracket [%.6g, %.6g]\n", low, high);
    expect(low <= 0.93 && 0.93 < high, "the limit lies in the bracket");
    expect(high - low <= 0.005 * high, "the bracket is within r of it");
  }

  std::cout << "* halving after a failure at 1 from 0.9\n";
  {
    LoadStepping stepping(programme({0.9, 0.1}, 0.01), false, 10);
    stepping.report(result(true, 1));
    std::vector<double> attempts;
    for (unsigned int k = 0; k < 4; ++k)
      {
        attempts.push_back(stepping.target());
        stepping.report(result(false, 100));
      }
    std::printf("  attempts %.6g, %.6g, %.6g, %.6g\n",
                attempts[0],
                attempts[1],
                attempts[2],
                attempts[3]);
    expect(attempts[0] == 1 && std::abs(attempts[1] - 0.95) < 1e-15 &&
             std::abs(attempts[2] - 0.925) < 1e-15 &&
             std::abs(attempts[3] - 0.9125) < 1e-15,
           "each failed step is halved");
  }

  std::cout << "* growth after a cut: easy steps double, hard ones keep\n";
  {
    LoadStepping stepping(programme({1.6}, 0.01), false, 5);
    stepping.report(result(false, 100)); // 1.6 fails
    stepping.report(result(false, 100)); // 0.8 fails
    const double cut = stepping.target();
    stepping.report(result(true, 20)); // hard
    const double after_hard = stepping.target();
    stepping.report(result(true, 2)); // easy
    const double after_easy = stepping.target();
    std::printf("  after two cuts %.6g, after a hard step %.6g, after an "
                "easy one %.6g\n",
                cut,
                after_hard,
                after_easy);
    expect(cut == 0.4 && after_hard == 0.8 && after_easy == 1.6,
           "a hard step keeps the cut length, an easy one doubles it");
  }

  std::cout << "* the programme as given (r = 0)\n";
  {
    LoadStepping stepping(programme({0.5, 0.25, 0.25}, 0), false, 10);
    const auto [low, high] = run(stepping, 0.6, 3);
    expect(low == 0.5 && high == 0.75, "the first failure ends the run");
    LoadStepping going_on(programme({0.5, 0.25, 0.25}, 0), true, 10);
    const auto [last, end] = run(going_on, 0.6, 3);
    expect(last == 1 && going_on.finished(),
           "with Continue after failure the programme goes on");
  }

  std::cout << "* a non-finite result\n";
  {
    LoadStepping stepping(programme({0.5, 0.5}, 0.01), false, 10);
    StepResult   r = result(false, 3);
    r.non_finite   = true;
    expect(stepping.report(r) == LoadStepping::Next::stop,
           "stops the run at once");
  }

  std::cout << "* a programme without failures\n";
  {
    LoadStepping        stepping(programme({0.3, 0.3, 0.1}, 0.01), false, 10);
    std::vector<double> attempted;
    while (!stepping.finished())
      {
        attempted.push_back(stepping.target());
        stepping.report(result(true, 1));
      }
    expect(attempted.size() == 3 && attempted[0] == 0.3 &&
             attempted[1] == 0.3 + 0.3 && attempted[2] == 0.3 + 0.3 + 0.1,
           "attempts exactly the programme's running sums");
  }

  std::cout << "* adaptive step length, limit 1.0037, Prandtl's programme "
               "(0.5, 3*0.1, 20*0.01, 10*0.02), r = 0.005\n";
  {
    LoadStepping by_programme(programme(prandtl_programme(), 0.005), false, 10);
    LoadStepping adaptive(programme(prandtl_programme(), 0.005, true),
                          false,
                          10);
    const Walk   given   = walk(by_programme, 1.0037, 10, 3);
    const Walk   adapted = walk(adaptive, 1.0037, 10, 3);
    std::printf("  programme: bracket [%.6g, %.6g] in %u attempts; adaptive: "
                "[%.6g, %.6g] in %u attempts\n",
                given.low,
                given.high,
                given.attempts,
                adapted.low,
                adapted.high,
                adapted.attempts);
    expect(adapted.low <= 1.0037 && 1.0037 < adapted.high &&
             adapted.high - adapted.low <= 0.005 * adapted.high,
           "adaptive: the limit bracketed within r");
    expect(!adapted.passed_a_failure,
           "adaptive: no attempt past a load factor that failed");
    expect(2 * adapted.attempts <= given.attempts,
           "adaptive: at most half the programme's attempts");
  }

  std::cout << "* adaptive, steps longer than 0.2 fail, no limit below the "
               "end 1.2\n";
  {
    LoadStepping adaptive(programme(prandtl_programme(), 0.005, true),
                          false,
                          10);
    const Walk   walked = walk(adaptive, 10, 0.2, 3);
    std::printf("  ends at %.6g after %u attempts, longest step %.6g\n",
                walked.low,
                walked.attempts,
                walked.longest_step);
    expect(adaptive.finished() && std::abs(walked.low - 1.2) < 1e-12,
           "failures of steps too long are passed: the programme's end "
           "reached");
    expect(!walked.passed_a_failure,
           "no attempt past a load factor that failed before a state there "
           "converged");
    expect(walked.longest_step > 0.1,
           "steps grew past the programme's increments");
  }

  std::cout << "* adaptive growth: easy steps double, ones over twice the "
               "easy iterations halve\n";
  {
    LoadStepping adaptive(programme({1, 99}, 0.005, true), false, 10);
    stepping_report_converged(adaptive, 2); // 1: easy
    const double after_easy = adaptive.target();
    stepping_report_converged(adaptive, 15); // 3: hard
    const double after_hard = adaptive.target();
    stepping_report_converged(adaptive, 25); // 5: near the budget
    const double after_slow = adaptive.target();
    std::printf("  targets %.6g, %.6g, %.6g\n",
                after_easy,
                after_hard,
                after_slow);
    expect(after_easy == 3 && after_hard == 5 && after_slow == 6,
           "lengths 2 after an easy step, 2 after a hard one, 1 after a "
           "slow one");
  }

  std::cout << "* every run above\n";
  expect(final_mispredicted == 0,
         "failure_is_final() foretold, before each failed attempt, whether "
         "it would be kept (ending the run, or accepted) rather than cut "
         "back");

  return truths::conclude();
}
