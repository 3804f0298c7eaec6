#include <thinlayer/stepping/load_stepping.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  LoadStepping::LoadStepping(const LoadingParameters &loading,
                             const bool               continue_after_failure,
                             const unsigned int       easy_iterations)
    : increments(loading.load_increments)
    , resolution(loading.collapse_resolution)
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
    // without cut-backs attempts exactly the programme's load factors.
    const double remaining = targets[next_target] - accepted;
    return std::abs(increment) >= std::abs(remaining) * (1 - 1e-12)
             ? targets[next_target]
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
        advance(result.iterations <= easy_iterations);
        return Next::accept;
      }
    if (result.non_finite)
      return Next::stop;

    if (automatic())
      {
        if (failure_is_final())
          return Next::stop;
        increment = (target() - accepted) / 2;
        ++step_cuts;
        return Next::retry;
      }
    if (continue_after_failure)
      {
        advance(false);
        return Next::accept_failed;
      }
    return Next::stop;
  }


  void
  LoadStepping::advance(const bool easy)
  {
    const double reached = target();
    // Whether this step was shorter than the programme's: then it grows
    // back towards that.
    const bool cut_short =
      std::abs(increment) < std::abs(increments[next_target]) * (1 - 1e-12);
    ++steps;
    step_cuts = 0;
    if (reached == targets[next_target])
      ++next_target;
    accepted = reached;
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
