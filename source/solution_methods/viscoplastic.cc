#include <thinlayer/base/interruption.h>
#include <thinlayer/solution_methods/step_progress.h>
#include <thinlayer/solution_methods/viscoplastic.h>

#include <algorithm>

namespace thinlayer
{
  namespace
  {
    /**
     * The nearest 32-bit real of each entry this rank owns: what a code
     * that stores a vector in single precision keeps of it
     * (Solver/Single precision).
     */
    void
    round_to_single(ModeVector &v)
    {
      for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
        v.local_element(i) = static_cast<float>(v.local_element(i));
    }
  } // namespace


  template <int dim>
  ViscoplasticMethod<dim>::ViscoplasticMethod(
    const SolverParameters &parameters,
    IterationAccess<dim>   &analysis)
    : parameters(parameters)
    , analysis(analysis)
  {}


  template <int dim>
  void
  ViscoplasticMethod<dim>::initialize()
  {
    previous_increment = analysis.new_mode_vectors();
    body_loads         = analysis.new_mode_vectors();
    body_load_change   = analysis.new_mode_vectors();
  }


  template <int dim>
  void
  ViscoplasticMethod<dim>::solve_increments(const double dlambda)
  {
    ModeVectors &increments = analysis.get_step_increment();
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        increments[m] = body_loads[m];
        increments[m].add(dlambda, analysis.get_mode_system(m).unit_rhs);
        analysis.get_mode_system(m).condense(increments[m]);
      }
    analysis.elastic_solve(increments);
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const ModeSystem &mode = analysis.get_mode_system(m);
        mode.distribute(increments[m]);
        increments[m].add(dlambda, mode.unit_prescribed_displacement);
        if (parameters.single_precision)
          round_to_single(increments[m]);
      }
  }


  template <int dim>
  StepResult
  ViscoplasticMethod<dim>::solve_step(const double new_load_factor)
  {
    const double dlambda = new_load_factor - analysis.accepted_load_factor();
    const unsigned int n_modes = analysis.n_modes();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        body_loads[m]                    = 0;
        analysis.get_step_increment()[m] = 0;
        previous_increment[m]            = 0;
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
            previous_increment[m] = analysis.get_step_increment()[m];
            body_load_change[m]   = 0;
          }
        solve_increments(dlambda);

        result.plastic_points = analysis.viscoplastic_update(body_load_change);

        // The criteria take the largest entry over all modes.
        double change = 0, size = 0;
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            const ModeVector &increment = analysis.get_step_increment()[m];
            // The body loads are kept condensed (condensing is linear, and
            // idempotent, so solve_increments() may condense them again):
            // the criterion reads them with no copy.
            analysis.get_mode_system(m).condense(body_load_change[m]);
            body_loads[m] += body_load_change[m];
            if (parameters.single_precision)
              round_to_single(body_loads[m]);
            if (body_load_criterion)
              {
                change = std::max(change, body_load_change[m].linfty_norm());
                size   = std::max(size, body_loads[m].linfty_norm());
              }
            else
              {
                previous_increment[m] -= increment;
                change = std::max(change, previous_increment[m].linfty_norm());
                size   = std::max(size, increment.linfty_norm());
              }
          }
        if (result.plastic_points == 0)
          result.converged = true; // elastic: nothing will change
        else if (body_load_criterion || result.iterations > 1)
          result.converged = (change <= parameters.tolerance * size);
        growth.iteration_done(result.iterations,
                              parameters.max_iterations,
                              analysis.get_step_increment());
        report_iteration(result.iterations,
                         body_load_criterion ? "body-load change"
                                             : "displacement change",
                         size > 0 ? change / size : 0.);
      }
    if (!result.converged)
      result.growth_ratio = growth.growth_ratio(analysis.get_step_increment());

    return result;
  }


  template <int dim>
  bool
  ViscoplasticMethod<dim>::returns_stresses_to_surface() const
  {
    return false;
  }


  template class ViscoplasticMethod<2>;
  template class ViscoplasticMethod<3>;
} // namespace thinlayer
