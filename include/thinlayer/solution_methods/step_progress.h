#ifndef thinlayer_solution_methods_step_progress_h
#define thinlayer_solution_methods_step_progress_h

#include <chrono>
#include <ostream>
#include <string>

namespace thinlayer
{
  /**
   * A line on screen every Output/Progress interval seconds (5 by
   * default) while a load step iterates, so that a long step on a fine
   * mesh shows it is alive and how near it is to converging. The run opens
   * one per attempt; the solution methods call report_iteration() after
   * each iteration without knowing whether anyone listens (none does in
   * short steps, nor where the interval is 0: the tests, whose compared
   * screen output must not depend on how busy the machine is).
   */
  class StepProgress
  {
  public:
    /// Report on @p out every @p interval seconds (never if 0) while
    /// alive, for the attempt at @p load_factor.
    StepProgress(std::ostream &out,
                 unsigned int  step,
                 double        load_factor,
                 double        interval);
    ~StepProgress();

    StepProgress(const StepProgress &) = delete;
    StepProgress &
    operator=(const StepProgress &) = delete;

  private:
    friend void
    report_iteration(unsigned int, const char *, double);

    std::ostream                         &out;
    const unsigned int                    step;
    const double                          load_factor;
    const std::chrono::duration<double>   interval;
    std::chrono::steady_clock::time_point start;
    std::chrono::steady_clock::time_point next_line;
  };

  /**
   * After iteration @p iteration of the current attempt: its convergence
   * measure, named @p measure ("residual") with @p value relative to the
   * tolerance's scale. Prints only if a StepProgress with an interval is
   * open and that interval has passed since its last line.
   */
  void
  report_iteration(unsigned int iteration, const char *measure, double value);
} // namespace thinlayer

#endif
