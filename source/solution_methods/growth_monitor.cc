#include <thinlayer/solution_methods/growth_monitor.h>

#include <algorithm>
#include <limits>

namespace thinlayer
{
  void
  GrowthMonitor::start(const ModeVectors &step_increment)
  {
    first          = step_increment;
    change_at_half = 0;
  }


  void
  GrowthMonitor::iteration_done(const unsigned int iteration,
                                const unsigned int limit,
                                const ModeVectors &step_increment)
  {
    if (iteration == 1)
      start(step_increment);
    else if (iteration == limit / 2)
      change_at_half = change(step_increment);
  }


  double
  GrowthMonitor::growth_ratio(const ModeVectors &step_increment)
  {
    if (!(change_at_half > 0))
      return std::numeric_limits<double>::quiet_NaN();
    return change(step_increment) / change_at_half;
  }


  double
  GrowthMonitor::change(const ModeVectors &step_increment)
  {
    double result = 0;
    for (unsigned int m = 0; m < step_increment.size(); ++m)
      {
        work = step_increment[m];
        work -= first[m];
        result = std::max(result, work.linfty_norm());
      }
    return result;
  }
} // namespace thinlayer
