#include <thinlayer/base/interruption.h>
#include <thinlayer/solution_methods/viscoplastic.h>
#include <thinlayer/stepping/step_progress.h>

#include <algorithm>

namespace thinlayer
{
  template <int dim>
  ViscoplasticMethod<dim>::ViscoplasticMethod(
    const SolverParameters &parameters,
    Analysis<dim>          &analysis)
    : parameters(parameters)
    , analysis(analysis)
  {}


  template <int dim>
  void
  ViscoplasticMethod<dim>::initialize()
  {
    previous_increment.assign(
      analysis.n_modes(), Vector<double>(analysis.get_dof_handler().n_dofs()));
  }


  template <int dim>
  void
  ViscoplasticMethod<dim>::solve_increment(const unsigned int m,
                                           const double       dlambda)
  {
    ModeState      &mode      = analysis.mode(m);
    Vector<double> &increment = mode.step_increment;
    increment                 = mode.body_loads;
    increment.add(dlambda, mode.unit_rhs);
    mode.constraints.condense(increment);
    mode.factorisation.solve(increment);
    mode.constraints.distribute(increment);
    increment.add(dlambda, mode.unit_prescribed_displacement);
  }


  template <int dim>
  StepResult
  ViscoplasticMethod<dim>::solve_step(const double new_load_factor)
  {
    const double dlambda = new_load_factor - analysis.accepted_load_factor();
    const unsigned int n_modes = analysis.n_modes();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        analysis.mode(m).body_loads     = 0;
        analysis.mode(m).step_increment = 0;
        previous_increment[m]           = 0;
      }

    const bool body_load_criterion =
      (parameters.convergence_criterion ==
       SolverParameters::ConvergenceCriterion::body_loads);
    StepResult result{0, false, 0, 0};
    while (result.iterations < parameters.max_iterations && !result.converged &&
           !interrupted())
      {
        ++result.iterations;
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            previous_increment[m] = analysis.mode(m).step_increment;
            solve_increment(m, dlambda);
            analysis.mode(m).body_load_change = 0;
          }

        result.plastic_points = analysis.update_viscoplastic_stresses();

        // The criteria take the largest entry over all modes.
        double change = 0, size = 0;
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            ModeState &mode = analysis.mode(m);
            // The body loads are kept condensed (condensing is linear, and
            // idempotent, so solve_increment() may condense them again):
            // the criterion reads them with no copy.
            mode.constraints.condense(mode.body_load_change);
            mode.body_loads += mode.body_load_change;
            if (body_load_criterion)
              {
                change = std::max(change, mode.body_load_change.linfty_norm());
                size   = std::max(size, mode.body_loads.linfty_norm());
              }
            else
              {
                previous_increment[m] -= mode.step_increment;
                change = std::max(change, previous_increment[m].linfty_norm());
                size   = std::max(size, mode.step_increment.linfty_norm());
              }
          }
        if (result.plastic_points == 0)
          result.converged = true; // elastic: nothing will change
        else if (body_load_criterion || result.iterations > 1)
          result.converged = (change <= parameters.tolerance * size);
        growth.iteration_done(result.iterations,
                              parameters.max_iterations,
                              analysis.get_modes());
        report_iteration(result.iterations,
                         body_load_criterion ? "body-load change"
                                             : "displacement change",
                         size > 0 ? change / size : 0.);
      }
    if (!result.converged)
      result.growth_ratio = growth.growth_ratio(analysis.get_modes());

    return result;
  }


  template class ViscoplasticMethod<2>;
} // namespace thinlayer
