#include <thinlayer/solution_methods/convergence_watch.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  void
  ConvergenceWatch::start()
  {
    residuals.clear();
  }


  void
  ConvergenceWatch::add(const double residual)
  {
    residuals.push_back(std::isfinite(residual)
                          ? residual
                          : std::numeric_limits<double>::infinity());
  }


  unsigned int
  ConvergenceWatch::iterations() const
  {
    return residuals.size();
  }


  bool
  ConvergenceWatch::stagnating(const unsigned int window,
                               const double       factor) const
  {
    const std::size_t n = residuals.size();
    if (window == 0 || n < 2 * window)
      return false;
    const double best_before =
      *std::min_element(residuals.begin(), residuals.end() - window);
    const double best_since =
      *std::min_element(residuals.end() - window, residuals.end());
    return !(best_since < factor * best_before);
  }


  double
  ConvergenceWatch::predicted_iterations(const double       target,
                                         const unsigned int window) const
  {
    const std::size_t n = residuals.size();
    if (window == 0 || n < window + 1)
      return std::numeric_limits<double>::quiet_NaN();
    const double last  = residuals[n - 1];
    const double first = residuals[n - 1 - window];
    if (last <= target)
      return n;
    if (!(last < first) || !(last > 0))
      return std::numeric_limits<double>::infinity();
    const double rate = std::log(last / first) / window; // < 0
    return n + std::log(target / last) / rate;
  }
} // namespace thinlayer
