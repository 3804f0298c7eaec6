#ifndef thinlayer_solvers_factor_cost_h
#define thinlayer_solvers_factor_cost_h

namespace thinlayer
{
  /**
   * What a factor costs in floating-point operations, as its solver's
   * symbolic analysis counts them: its factorisation, and one substitution
   * (a forward and a backward solve with one right-hand side). The counts
   * depend on the sparsity pattern and the ordering alone, so that a
   * choice made from them (NewtonFallbackMethod's budget of cheap
   * iterations) is the same on every run of a scene, whatever the machine's
   * load; times would not be.
   */
  struct FactorCost
  {
    double factorisation = 0;
    double substitution  = 0;

    /// Whether there is a factor to count (an iterative solver has none).
    bool
    known() const
    {
      return substitution > 0;
    }
  };
} // namespace thinlayer

#endif
