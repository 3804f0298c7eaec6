#include <thinlayer/solution_methods/newton_fallback.h>

namespace thinlayer
{
  template <int dim>
  NewtonFallbackMethod<dim>::NewtonFallbackMethod(
    const SolverParameters &parameters,
    Analysis<dim>          &analysis)
    : accelerated(parameters, analysis)
    , newton(parameters, analysis)
  {}


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

    // Newton starts again from the accepted state (its tangents are those
    // of that state), so the accelerated attempt leaves nothing behind.
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


  template class NewtonFallbackMethod<2>;
} // namespace thinlayer
