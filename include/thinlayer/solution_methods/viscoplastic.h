#ifndef thinlayer_solution_methods_viscoplastic_h
#define thinlayer_solution_methods_viscoplastic_h

#include <thinlayer/analysis/iteration_access.h>
#include <thinlayer/solution_methods/growth_monitor.h>
#include <thinlayer/solution_methods/solution_method.h>

#include <vector>

namespace thinlayer
{
  /**
   * The paper's method: constant-stiffness viscoplastic strain iterations.
   * A load step from lambda_0 to lambda solves, with body loads b_m = 0 at
   * its start,
   *   K_m du_m = (lambda - lambda_0) f_m + b_m     for every mode m,
   * then at every point and station d eps = strain - eps_vp,
   * sigma = sigma_0 + D d eps; where F(sigma) > 0 it adds the viscoplastic
   * strain dt F dQ/dsigma to eps_vp and projects D (that strain) back onto
   * every mode's body loads, until the body loads (or the displacement
   * increments) stop changing to within the tolerance. A step that reaches
   * the iteration limit has failed: that is how collapse shows.
   *
   * The stresses are in equilibrium with the loads at every iteration; what
   * is out of balance is the change of the body loads, which the paper's
   * criterion measures.
   */
  template <int dim>
  class ViscoplasticMethod : public SolutionMethod<dim>
  {
  public:
    ViscoplasticMethod(const SolverParameters &parameters,
                       IterationAccess<dim>   &analysis);

    void
    initialize() override;

    StepResult
    solve_step(const double new_load_factor) override;

    /// false: the stresses keep the excess the last increment did not
    /// relax, to TOL (the drift that history.csv's max_yield_ratio shows).
    bool
    returns_stresses_to_surface() const override;

  private:
    /// Every mode's step increment for the load increment @p dlambda and
    /// the current body loads.
    void
    solve_increments(const double dlambda);

    const SolverParameters &parameters;
    IterationAccess<dim>   &analysis;
    /// Per mode: the step increment of the previous iteration.
    ModeVectors previous_increment;
    /// Per mode: the step's accumulated body loads (kept condensed), and
    /// those of the last iteration's viscoplastic strains.
    ModeVectors   body_loads;
    ModeVectors   body_load_change;
    GrowthMonitor growth;
  };
} // namespace thinlayer

#endif
