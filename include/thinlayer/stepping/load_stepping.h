#ifndef thinlayer_stepping_load_stepping_h
#define thinlayer_stepping_load_stepping_h

#include <thinlayer/parameters/parameters.h>
#include <thinlayer/solution_methods/step_result.h>

#include <vector>

namespace thinlayer
{
  /**
   * The load factors a run attempts. The scene's increments (Loading/Load
   * increments) are the programme: the targets are their running sums.
   *
   * With a collapse resolution r > 0 (the default) the stepping is
   * automatic: a step that fails is halved and tried again from the last
   * accepted state, and after every easy converged step (few iterations)
   * the increment doubles again, up to the programme's own. (Growing after
   * every converged step makes every second attempt fail where only small
   * steps converge, each failure costing the whole iteration limit.) A step
   * that still fails when it is no longer than r times its target load factor
   * (or than r times the first increment, for a collapse load near zero) ends
   * the run: the collapse load is then bracketed between the last accepted load
   * factor and that target to within r. With r = 0 the programme is run as
   * given (the paper's way): the first failed step ends it, or, with
   * Solver/Continue after failure, its state is accepted and the
   * programme goes on (with automatic stepping a failure that is bracketed
   * always ends the run: going on from a collapsed state would only
   * bracket the same collapse again at every step).
   *
   * With Loading/Step length = adaptive the programme's targets between
   * its first step and its end are dropped: the first step is the
   * programme's first increment, and the step doubles after every easy
   * step, keeps its length after a hard one and halves after one that
   * took more than twice an easy one's iterations, unbounded by the
   * programme's increments. A programme of small steps near collapse then
   * costs as many steps as the response needs rather than as many as its
   * author wrote. A load factor whose attempt failed is never passed until
   * a state there converged (the step reaches it, not beyond): growing
   * past a failure would only fail again where the failure is a limit.
   * One that fails again from nearer is bisected (advance()).
   *
   * The stepping decides only which load factor comes next; whether a
   * failure that ends a run is a collapse is the run's to judge
   * (run_scene()), and so is whether a converged step is to count as one
   * that failed (under load, a step that converged on the mechanism is
   * reported here as failed, so that the knee is bracketed like a limit).
   */
  class LoadStepping
  {
  public:
    /// What to do with the state of an attempt.
    enum class Next
    {
      /// Accept it and go on.
      accept,
      /// Drop it and try again with a smaller step.
      retry,
      /// A failed step that ends no run: accept it and go on.
      accept_failed,
      /// A failed step that ends the run.
      stop
    };

    /**
     * The programme of @p loading. A converged step counts as easy (and the
     * next one may grow) when it took at most @p easy_iterations
     * iterations.
     */
    LoadStepping(const LoadingParameters &loading,
                 const bool               continue_after_failure,
                 const unsigned int       easy_iterations);

    /// Whether the programme's last target has been reached.
    bool
    finished() const;

    /// The load factor of the next attempt.
    double
    target() const;

    /// The number of the step being attempted: accepted steps plus one.
    unsigned int
    step() const;

    /// Whether a failure is cut back and retried.
    bool
    automatic() const;

    /**
     * Whether a failure of the attempt at target() would be final: no
     * cut-back follows (the programme as given, or a step already at the
     * collapse resolution). Such an attempt is the evidence of how the run
     * ended, so its method runs it to its iteration limit rather than
     * giving it up early (SolutionMethod::set_final_attempt()).
     */
    bool
    failure_is_final() const;

    /**
     * Take the result of the attempt at target() and say what to do with
     * its state. A non-finite result always stops the run.
     */
    Next
    report(const StepResult &result);


  private:
    /// Move on after a step to target() was accepted, which took
    /// @p iterations: it may grow where they were few.
    void
    advance(const unsigned int iterations);

    const std::vector<double> increments;
    const double              resolution;
    /// Loading/Step length = adaptive.
    const bool         adaptive;
    const bool         continue_after_failure;
    const unsigned int easy_iterations;
    /// The programme's targets: running sums of the increments.
    std::vector<double> targets;
    /// The programme target being walked to.
    unsigned int next_target;
    double       accepted;
    /// The current step length.
    double       increment;
    unsigned int steps;
    /// Halvings of the current step.
    unsigned int                  step_cuts;
    static constexpr unsigned int max_step_cuts = 60;
    /// Adaptive: a load factor beyond the accepted one whose attempt
    /// failed, the length of that step, and whether it failed again from
    /// nearer (a limit, bracketed by bisection).
    struct Failure
    {
      double target;
      double step;
      bool   bisecting;
    };
    /// The failures no step has passed yet, the nearest last: no step
    /// reaches past it.
    std::vector<Failure> failures;
  };
} // namespace thinlayer

#endif
