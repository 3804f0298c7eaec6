#include <thinlayer/stepping/step_solver.h>

#include <cmath>

namespace thinlayer
{
  template <int dim>
  StepSolver<dim>::StepSolver(const SolverParameters &parameters,
                              StepAccess<dim>        &analysis)
    : analysis(analysis)
    , method(create_solution_method(parameters, analysis))
    , tolerance(parameters.tolerance)
  {
    method->initialize();
  }


  template <int dim>
  StepSolver<dim>::~StepSolver() = default;


  template <int dim>
  StepResult
  StepSolver<dim>::solve(const double load_factor, const bool final)
  {
    method->set_final_attempt(final);
    StepResult result = method->solve_step(load_factor);
    if (!work_control)
      result.load_factor = load_factor;
    else if (!std::isfinite(result.load_factor))
      {
        // No load factor to hold the state at: the accepted one's.
        result.non_finite  = true;
        result.load_factor = analysis.accepted_load_factor();
      }
    const StateCheck check = analysis.end_attempt(result.load_factor);
    result.max_yield_ratio = check.max_yield_ratio;
    if (!check.finite)
      {
        result.non_finite = true;
        result.converged  = false;
      }
    else if (result.converged && method->returns_stresses_to_surface() &&
             result.max_yield_ratio > 10 * tolerance)
      {
        result.outside_surface = true;
        result.converged       = false;
      }
    return result;
  }


  template <int dim>
  void
  StepSolver<dim>::set_work_control(const bool on)
  {
    method->set_work_control(on);
    work_control = on;
  }


  template <int dim>
  void
  StepSolver<dim>::begin_phase()
  {
    method->initialize();
  }


  template <int dim>
  void
  StepSolver<dim>::accept()
  {
    Assert(analysis.is_pending(),
           ExcMessage("There is no pending step to accept."));
    analysis.accept_step();
    method->state_accepted();
  }


  template <int dim>
  void
  StepSolver<dim>::reject()
  {
    analysis.reject_step();
    method->state_rejected();
  }


  template class StepSolver<2>;
  template class StepSolver<3>;
} // namespace thinlayer
