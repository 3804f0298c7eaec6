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
   * iterations); a step it cannot converge within its budget of iterations
   * is tried again from the accepted state by Newton's method (consistent
   * tangent, line search). Away from collapse the cheap method does the
   * work; near it, where constant-stiffness iterations creep and Anderson's
   * extrapolation can stall, Newton decides whether the step has an
   * equilibrium, so the collapse load is Newton's.
   *
   * How long the cheap method may try a step is a rent-or-buy choice: by
   * what a step by Newton costs, in the cheap method's iterations. That is
   * counted from the operations of the tangent's factor and of the elastic
   * factors, as the direct solvers' analyses count them
   * (newton_cost_in_cheap_iterations()): before Newton has converged a step
   * as five iterations with a tangent as dear as the elastic stiffness,
   * after as Newton's last converged step. The counts, not the clock, make
   * the choice, so that a scene takes the same path on every run.
   *
   * - Where Newton's step costs no more than Solver/Maximum iterations
   *   cheap iterations (plane strain, where a factorisation costs some
   *   tens of substitutions at most), a failed cheap attempt would cost as
   *   much as the Newton step after it. The cheap method has 100 iterations
   *   (or Solver/Maximum iterations, if fewer) and gives an attempt up as
   *   soon as its rate says it will not converge within them; once Newton
   *   has converged a step, it takes every step from then on: the plastic
   *   zone has grown to where the elastic stiffness converges slowly.
   * - Where it costs more (3D, where a factorisation costs many tens of
   *   substitutions), even a cheap attempt that runs to the limit and fails
   *   costs less than Newton's step. The cheap method has Solver/Maximum
   *   iterations and runs to them (Anderson's residual wanders and its
   *   convergence speeds up as its history fills: on the first plastic
   *   steps of prm/circular-footing-rigid-3d.prm its early rate gave up
   *   attempts that converged well within the limit), and goes on taking
   *   the steps it can: after a failure the next 1, 2, 4, ... steps go to
   *   Newton directly (doubling with each further failure, back to none
   *   after a success), and it is tried only while it was last seen to cost
   *   less than Newton's step.
   *
   * Where no factor's cost is known (Solver/Linear solver = amg cg) Newton's
   * steps are taken as cheap.
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

    /// Yes, by Newton alone: the accelerated method's corrections come of
    /// the elastic factor, which gives no load factor's correction.
    bool
    supports_work_control() const override;

    void
    set_work_control(const bool on) override;

  private:
    /**
     * What Newton's step @p step cost, in iterations of the cheap method:
     * its factorisations and substitutions (Krylov iterations too, each
     * one) with the tangent's factor against one substitution with the
     * elastic factors of every mode. Zero where a cost is unknown.
     */
    double
    newton_cost_in_cheap_iterations(const StepResult &step);

    /// The solver parameters of the accelerated method: its iteration
    /// limit is the budget of the attempt.
    SolverParameters                    accelerated_parameters;
    AcceleratedInitialStressMethod<dim> accelerated;
    NewtonMethod<dim>                   newton;
    const AnalysisView<dim>            &analysis;
    /// Solver/Maximum iterations: no budget goes beyond it.
    const unsigned int max_iterations;
    /// What a step by Newton costs, in cheap iterations, and whether that
    /// is more than the cheap method's whole limit.
    double newton_step_cost = 0;
    bool   dear_newton      = false;
    /// The cheap method's budget for an attempt.
    unsigned int budget = 0;
    /// Where Newton is cheap: it has converged a step and takes them all.
    bool newton_only = false;
    /// Under work control every step is Newton's.
    bool work_control = false;
    /// Where Newton is dear: what the cheap method's last attempt cost
    /// (one more than its budget where it failed), the steps still to go
    /// to Newton directly, and how many the next failure sends there.
    unsigned int cheap_step_cost            = 0;
    unsigned int newton_steps_left          = 0;
    unsigned int newton_steps_after_failure = 1;
    /// The tangent's factor cost, kept from its last factorisation.
    FactorCost tangent;
  };
} // namespace thinlayer

#endif
