#ifndef thinlayer_solution_methods_newton_fallback_h
#define thinlayer_solution_methods_newton_fallback_h

#include <thinlayer/solution_methods/accelerated_initial_stress.h>
#include <thinlayer/solution_methods/newton.h>
#include <thinlayer/solution_methods/solution_method.h>

namespace thinlayer
{
  /**
   * Accelerated initial stress, safeguarded by Newton: each load step is
   * first iterated with the constant elastic stiffness and Anderson
   * acceleration (one factorisation for the whole analysis, cheap
   * iterations); a step it cannot converge within 100 iterations (or
   * Solver/Maximum iterations, if fewer) is tried again from the accepted
   * state by Newton's method (consistent tangent, line search).
   * Away from collapse the cheap method does the work; near it, where
   * constant-stiffness iterations creep and Anderson's extrapolation can
   * stall, Newton decides whether the step has an equilibrium, so the
   * collapse load is Newton's.
   *
   * Once Newton has had to converge a step, the following steps go to it
   * directly: the plastic zone has then grown to where the elastic
   * stiffness converges slowly, and each step would first spend the whole
   * iteration limit of the cheap method before the few of Newton's that
   * decide it (the benchmarks' Case 3 at aspect ratio 1000 shows it).
   *
   * Both methods keep their state; both are told of accepted and rejected
   * states.
   */
  template <int dim>
  class NewtonFallbackMethod : public SolutionMethod<dim>
  {
  public:
    NewtonFallbackMethod(const SolverParameters &parameters,
                         IterationAccess<dim>   &analysis);

    void
    initialize() override;

    StepResult
    solve_step(const double new_load_factor) override;

    void
    state_accepted() override;

    void
    state_rejected() override;

    /// Newton's attempt is the one a final failure shows; the accelerated
    /// part may give up early whatever (Newton takes the step over).
    void
    set_final_attempt(const bool final) override;

  private:
    /// The solver parameters of the accelerated method: its iteration
    /// limit capped (accelerated_budget in the source).
    SolverParameters                    accelerated_parameters;
    AcceleratedInitialStressMethod<dim> accelerated;
    NewtonMethod<dim>                   newton;
    /// Newton has converged a step: it takes every step from now on.
    bool newton_only = false;
  };
} // namespace thinlayer

#endif
