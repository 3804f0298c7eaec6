#include <thinlayer/solution_methods/newton_fallback.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  namespace
  {
    /**
     * What a step by Newton is taken to cost before Newton has converged
     * one: this many iterations (the fewest a step that yields takes),
     * each factorising a tangent as dear as the elastic stiffness.
     */
    constexpr unsigned int first_newton_iterations = 5;

    /**
     * The cheap method's budget where Newton's steps are cheap.
     * Anderson-accelerated steps that converge at all do so in 5 to 70
     * iterations away from collapse (benchmarks/outcomes.py).
     */
    constexpr unsigned int cheap_newton_budget = 100;

    /**
     * How a factorisation's time grows against a substitution's with
     * their operations: as (operations ratio)^0.75. Its dense blocks run at
     * BLAS-3 speed, the faster the larger they are, where a substitution is
     * bound by memory. A plane-strain tangent's factorisation has some tens
     * of substitutions' operations and a 3D one some hundreds; the power
     * meets the times of both, as benchmarks/performance.py prints them,
     * within a factor of three, which the rent-or-buy choice tolerates.
     */
    constexpr double factorisation_exponent = 0.75;
  } // namespace


  template <int dim>
  NewtonFallbackMethod<dim>::NewtonFallbackMethod(
    const SolverParameters &parameters,
    IterationAccess<dim>   &analysis)
    : accelerated_parameters(parameters)
    , accelerated(accelerated_parameters, analysis)
    , newton(parameters, analysis)
    , analysis(analysis)
    , max_iterations(parameters.max_iterations)
  {
    accelerated.report_acceptance_to(*this);
    newton.report_acceptance_to(*this);
  }


  template <int dim>
  void
  NewtonFallbackMethod<dim>::initialize()
  {
    accelerated.initialize();
    newton.initialize();
    newton_steps_left          = 0;
    newton_steps_after_failure = 1;
    cheap_step_cost            = 0;
    newton_only                = false;
    // The tangent's pattern is the elastic stiffness's (one mode) or holds
    // it (the modes coupled): its factor is taken as dear to begin with.
    tangent = analysis.n_modes() > 0
                ? analysis.get_mode_system(0).elastic_cost()
                : FactorCost();
    StepResult first_step{first_newton_iterations, true, 0, 0};
    first_step.factorisations = first_newton_iterations;
    newton_step_cost          = newton_cost_in_cheap_iterations(first_step);
    dear_newton               = newton_step_cost > max_iterations;
    budget                    = dear_newton ? max_iterations
                                            : std::min(max_iterations, cheap_newton_budget);
    accelerated.give_up_when_slow(!dear_newton);
  }


  template <int dim>
  double
  NewtonFallbackMethod<dim>::newton_cost_in_cheap_iterations(
    const StepResult &step)
  {
    if (newton.tangent_cost().known())
      tangent = newton.tangent_cost();
    double elastic = 0;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const FactorCost mode = analysis.get_mode_system(m).elastic_cost();
        if (!mode.known())
          return 0;
        elastic += mode.substitution;
      }
    if (!tangent.known())
      return 0;
    const double factorisation =
      tangent.substitution *
      std::pow(tangent.factorisation / tangent.substitution,
               factorisation_exponent);
    return (step.factorisations * factorisation +
            (step.iterations + step.krylov_iterations) * tangent.substitution) /
           elastic;
  }


  template <int dim>
  StepResult
  NewtonFallbackMethod<dim>::solve_step(const double new_load_factor)
  {
    if (work_control)
      return newton.solve_step(new_load_factor);
    StepResult first{0, false, 0, 0};
    if (newton_steps_left > 0)
      --newton_steps_left;
    else if (!newton_only &&
             (!dear_newton || cheap_step_cost < newton_step_cost))
      {
        accelerated_parameters.max_iterations = budget;
        first = accelerated.solve_step(new_load_factor);
        // A failed attempt shows that a step needs more than its budget.
        cheap_step_cost = dear_newton ? first.iterations + !first.converged : 0;
        if (first.converged || first.non_finite)
          {
            newton_steps_after_failure = 1;
            return first;
          }
        if (dear_newton)
          {
            newton_steps_left = newton_steps_after_failure;
            newton_steps_after_failure =
              std::min(2 * newton_steps_after_failure, 1u << 20);
          }
      }

    // Newton starts again from the accepted state (its own predictor and
    // tangents), so the accelerated attempt leaves nothing behind.
    StepResult result = newton.solve_step(new_load_factor);
    if (result.converged)
      {
        if (dear_newton)
          newton_step_cost = newton_cost_in_cheap_iterations(result);
        else
          newton_only = true;
      }
    result.iterations += first.iterations;
    return result;
  }


  template <int dim>
  void
  NewtonFallbackMethod<dim>::state_accepted()
  {
    accelerated.state_accepted();
    newton.state_accepted();
  }


  template <int dim>
  void
  NewtonFallbackMethod<dim>::state_rejected()
  {
    accelerated.state_rejected();
    newton.state_rejected();
  }


  template <int dim>
  bool
  NewtonFallbackMethod<dim>::supports_work_control() const
  {
    return true;
  }


  template <int dim>
  void
  NewtonFallbackMethod<dim>::set_work_control(const bool on)
  {
    newton.set_work_control(on);
    work_control = on;
  }


  template <int dim>
  void
  NewtonFallbackMethod<dim>::set_final_attempt(const bool final)
  {
    accelerated.set_final_attempt(false);
    newton.set_final_attempt(final);
  }


  template class NewtonFallbackMethod<2>;
  template class NewtonFallbackMethod<3>;
} // namespace thinlayer
