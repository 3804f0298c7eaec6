#include <thinlayer/stepping/growth_monitor.h>

#include <algorithm>
#include <limits>

namespace thinlayer
{
  void
  GrowthMonitor::start(const std::vector<std::unique_ptr<ModeState>> &modes)
  {
    first.resize(modes.size());
    for (unsigned int m = 0; m < modes.size(); ++m)
      first[m] = modes[m]->step_increment;
    change_at_half = 0;
  }


  void
  GrowthMonitor::iteration_done(
    const unsigned int                             iteration,
    const unsigned int                             limit,
    const std::vector<std::unique_ptr<ModeState>> &modes)
  {
    if (iteration == 1)
      start(modes);
    else if (iteration == limit / 2)
      change_at_half = change(modes);
  }


  double
  GrowthMonitor::growth_ratio(
    const std::vector<std::unique_ptr<ModeState>> &modes)
  {
    if (!(change_at_half > 0))
      return std::numeric_limits<double>::quiet_NaN();
    return change(modes) / change_at_half;
  }


  double
  GrowthMonitor::change(const std::vector<std::unique_ptr<ModeState>> &modes)
  {
    double result = 0;
    for (unsigned int m = 0; m < modes.size(); ++m)
      {
        work = modes[m]->step_increment;
        work -= first[m];
        result = std::max(result, work.linfty_norm());
      }
    return result;
  }
} // namespace thinlayer
