#include <thinlayer/stepping/load_stepping.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  LoadStepping::LoadStepping(const LoadingParameters &loading,
                             const bool               continue_after_failure,
                             const unsigned int       easy_iterations)
    : increments(loading.load_increments)
    , resolution(loading.collapse_resolution)
    , adaptive(loading.step_length == LoadingParameters::StepLength::adaptive)
    , continue_after_failure(continue_after_failure)
    , easy_iterations(easy_iterations)
    , next_target(0)
    , accepted(0)
    , increment(loading.load_increments.front())
    , steps(0)
    , step_cuts(0)
  {
    double sum = 0;
    for (const double d : increments)
      targets.push_back(sum += d);
    // Adaptive: the end is the only target.
    if (adaptive)
      targets = {targets.back()};
  }


  bool
  LoadStepping::finished() const
  {
    return next_target == targets.size();
  }


  double
  LoadStepping::target() const
  {
    // The programme's own target when the step reaches it, so that a run
    // without cut-backs attempts exactly the programme's load factors; a
    // failed load factor likewise, where adaptive steps would pass it.
    const double goal =
      failures.empty() || std::abs(failures.back().target - accepted) >
                            std::abs(targets[next_target] - accepted)
        ? targets[next_target]
        : failures.back().target;
    const double remaining = goal - accepted;
    return std::abs(increment) >= std::abs(remaining) * (1 - 1e-12)
             ? goal
             : accepted + increment;
  }


  unsigned int
  LoadStepping::step() const
  {
    return steps + 1;
  }


  bool
  LoadStepping::automatic() const
  {
    return resolution > 0;
  }


  bool
  LoadStepping::failure_is_final() const
  {
    if (!automatic())
      return true;
    // Bracketed to the resolution of the load factor, or of the first
    // increment where the collapse load is near zero; and never more
    // than max_step_cuts halvings of one step.
    const double bracket =
      resolution * std::max(std::abs(target()), std::abs(increments.front()));
    return std::abs(target() - accepted) <= bracket ||
           step_cuts == max_step_cuts;
  }


  LoadStepping::Next
  LoadStepping::report(const StepResult &result)
  {
    if (result.converged)
      {
        advance(result.iterations);
        return Next::accept;
      }
    if (result.non_finite)
      return Next::stop;

    if (automatic())
      {
        if (failure_is_final())
          return Next::stop;
        const double failed = target();
        if (adaptive)
          {
            // A second failure at the same load factor, from nearer: a
            // limit, not a step too long. (A failure below one that is
            // bisected is on the bisection.)
            if (!failures.empty() && failed == failures.back().target)
              failures.back().bisecting = true;
            else
              failures.push_back(
                {failed,
                 failed - accepted,
                 !failures.empty() && failures.back().bisecting});
          }
        increment = (failed - accepted) / 2;
        ++step_cuts;
        return Next::retry;
      }
    if (continue_after_failure)
      {
        advance(easy_iterations + 1); // not an easy step
        return Next::accept_failed;
      }
    return Next::stop;
  }


  void
  LoadStepping::advance(const unsigned int iterations)
  {
    const bool   easy    = iterations <= easy_iterations;
    const double reached = target();
    // Whether this step was shorter than the programme's: then it grows
    // back towards that.
    const bool cut_short =
      std::abs(increment) < std::abs(increments[next_target]) * (1 - 1e-12);
    ++steps;
    step_cuts = 0;
    if (reached == targets[next_target])
      ++next_target;
    // A failed load factor converged: its failure came of a step too
    // long, of which half is the length to go on with (rather than the
    // short step that reached it). Failures further on still bound the
    // steps.
    const bool failure_passed =
      !failures.empty() && reached == failures.back().target;
    const double passed_step = failure_passed ? failures.back().step : 0;
    if (failure_passed)
      failures.pop_back();
    accepted = reached;
    if (adaptive)
      {
        // Unbounded by the programme: twice as long after an easy step,
        // half as long after one that took more than twice as many
        // iterations as an easy one (near the method's budget, where a
        // longer step would fail or fall back to a dearer method).
        if (easy)
          increment *= 2;
        else if (iterations > 2 * easy_iterations)
          increment /= 2;
        if (failure_passed && std::abs(increment) < std::abs(passed_step) / 2)
          increment = passed_step / 2;
        // Below a load factor that failed twice, bisect towards it: each
        // attempt then halves the bracket whether it converges or fails,
        // where reaching for the failed load factor after every converged
        // step would fail there once per halving at a limit. Once the
        // bracket is within the resolution, the failed load factor itself
        // is tried again with that short step: its failure is the
        // evidence of a collapse, its convergence shows the failures came
        // of steps too long. (After its first failure the failed load
        // factor is tried again from the converged half-way state: where
        // the step was merely too long, that passes it at once.)
        if (!failures.empty() && failures.back().bisecting)
          {
            const double failed_target = failures.back().target;
            const double remaining     = failed_target - reached;
            const double bracket =
              resolution *
              std::max(std::abs(failed_target), std::abs(increments.front()));
            if (std::abs(remaining) > bracket &&
                std::abs(increment) > std::abs(remaining) / 2)
              increment = remaining / 2;
          }
        return;
      }
    if (!finished())
      {
        // A step cut short grows back by doubling after an easy one, and
        // keeps its length after a hard one; never past the programme's.
        const double programme = increments[next_target];
        const double next =
          !cut_short ? programme : (easy ? 2 * increment : increment);
        increment = std::abs(next) < std::abs(programme) ? next : programme;
      }
  }
} // namespace thinlayer
