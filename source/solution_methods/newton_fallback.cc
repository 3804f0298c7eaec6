#include <thinlayer/solution_methods/newton_fallback.h>

#include <algorithm>

namespace thinlayer
{
  namespace
  {
    /**
     * The accelerated method's iterations per attempt before Newton takes
     * the step over. Anderson-accelerated steps that converge at all do so
     * in 5 to 70 iterations away from collapse (benchmarks/outcomes.py);
     * beyond that a few Newton iterations are cheaper. The cap trades the
     * cheap method's long creep near collapse against Newton's costlier
     * iterations; it leaves the collapse loads unchanged, and
     * benchmarks/outcomes.py measures the times that chose it.
     */
    constexpr unsigned int accelerated_budget = 100;
  } // namespace

  template <int dim>
  NewtonFallbackMethod<dim>::NewtonFallbackMethod(
    const SolverParameters &parameters,
    IterationAccess<dim>   &analysis)
    : accelerated_parameters(parameters)
    , accelerated(accelerated_parameters, analysis)
    , newton(parameters, analysis)
  {
    accelerated_parameters.max_iterations =
      std::min(parameters.max_iterations, accelerated_budget);
    accelerated.give_up_when_slow();
    accelerated.report_acceptance_to(*this);
    newton.report_acceptance_to(*this);
  }


  template <int dim>
  void
  NewtonFallbackMethod<dim>::initialize()
  {
    accelerated.initialize();
    newton.initialize();
    newton_only = false;
  }


  template <int dim>
  StepResult
  NewtonFallbackMethod<dim>::solve_step(const double new_load_factor)
  {
    if (newton_only)
      return newton.solve_step(new_load_factor);
    const StepResult first = accelerated.solve_step(new_load_factor);
    if (first.converged || first.non_finite)
      return first;

    // Newton starts again from the accepted state (its own predictor and
    // tangents), so the accelerated attempt leaves nothing behind.
    StepResult result = newton.solve_step(new_load_factor);
    newton_only       = result.converged;
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
  void
  NewtonFallbackMethod<dim>::set_final_attempt(const bool final)
  {
    accelerated.set_final_attempt(false);
    newton.set_final_attempt(final);
  }


  template class NewtonFallbackMethod<2>;
  template class NewtonFallbackMethod<3>;
} // namespace thinlayer
