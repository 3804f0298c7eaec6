#ifndef thinlayer_solution_methods_convergence_watch_h
#define thinlayer_solution_methods_convergence_watch_h

#include <vector>

namespace thinlayer
{
  /**
   * The residuals of one attempt at a load step, iteration by iteration
   * (relative: max |r| over the largest force), and what they say about
   * its end before the iteration limit is reached. An attempt that
   * cannot converge costs the whole limit, and near collapse, where
   * automatic stepping brackets the limit load by failed attempts, those
   * are most of a run's work (Prandtl's footing with 8192 cells by Newton:
   * three failed attempts of 25 iterations each, 75 of 246 iterations).
   * A method that sees its attempt going nowhere gives it up early:
   * - stagnating(): Newton's iterates converge quadratically once the set
   *   of yielding points has settled; while it is settling the residual
   *   may wander, but it reaches new lows. An attempt whose last
   *   iterations brought the residual nowhere near below its best before
   *   them is stuck on a state with no equilibrium near.
   * - predicted_iterations(): constant-stiffness iterations converge
   *   linearly; their rate over the last iterations says how many more
   *   they need.
   */
  class ConvergenceWatch
  {
  public:
    /// A new attempt.
    void
    start();

    /// The relative residual after one more iteration.
    void
    add(const double residual);

    unsigned int
    iterations() const;

    /**
     * Whether the last @p window residuals all stayed above @p factor
     * times the smallest one before them; false before 2 @p window
     * iterations. A residual that is not a finite number counts as no
     * progress.
     */
    bool
    stagnating(const unsigned int window, const double factor) const;

    /**
     * The iterations, counted from the start, at which the residual would
     * reach @p target if it went on falling at its mean rate over the last
     * @p window iterations; infinite where it has not fallen over them, NaN
     * before window + 1 iterations.
     */
    double
    predicted_iterations(const double target, const unsigned int window) const;

  private:
    std::vector<double> residuals;
  };
} // namespace thinlayer

#endif
