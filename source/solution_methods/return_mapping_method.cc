#include <thinlayer/base/interruption.h>
#include <thinlayer/solution_methods/return_mapping_method.h>
#include <thinlayer/solution_methods/step_progress.h>
#include <thinlayer/solution_methods/sub_stepping.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  template <int dim>
  ReturnMappingMethod<dim>::ReturnMappingMethod(
    const SolverParameters &parameters,
    IterationAccess<dim>   &analysis)
    : parameters(parameters)
    , analysis(analysis)
  {}


  template <int dim>
  void
  ReturnMappingMethod<dim>::initialize()
  {
    const ModeVectors zero = analysis.new_mode_vectors();
    correction             = zero;
    previous_increment     = zero;
    residual               = zero;
    accepted_increment     = zero;
    stress_excess          = zero;
    condensed              = zero[0];
    accepted_step          = 0;
    accepted_load_factor   = analysis.accepted_load_factor();
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::state_accepted()
  {
    accepted_increment = analysis.get_step_increment();
    accepted_step      = analysis.accepted_load_factor() - accepted_load_factor;
    accepted_load_factor = analysis.accepted_load_factor();
    accepted_step_work   = work_of(accepted_increment);
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::set_work_control(const bool on)
  {
    SolutionMethod<dim>::set_work_control(on);
    work_control = on;
  }


  template <int dim>
  double
  ReturnMappingMethod<dim>::work_of(const ModeVectors &displacements) const
  {
    double work = 0;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      work += analysis.get_mode_system(m).unit_load * displacements[m];
    return work;
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::predict_by_work()
  {
    const double scale =
      accepted_step_work > 0 ? step_work / accepted_step_work : 0;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        ModeVector &increment = analysis.get_step_increment()[m];
        increment             = accepted_increment[m];
        increment *= scale;
      }
    load_factor_now = analysis.accepted_load_factor();
  }


  template <int dim>
  ResidualNorms
  ReturnMappingMethod<dim>::starting_residual(const double target)
  {
    return evaluate_residual(target);
  }


  template <int dim>
  ResidualNorms
  ReturnMappingMethod<dim>::evaluate_residual(const double target,
                                              const bool   tangents)
  {
    ResidualNorms norms{analysis.return_mapping_update(tangents, stress_excess),
                        0,
                        0,
                        0,
                        0,
                        analysis.accepted_force_scale()};
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const ModeSystem &mode = analysis.get_mode_system(m);
        ModeVector       &r    = residual[m];
        r                      = mode.unit_load;
        r *= target;
        r += mode.held_load;
        norms.forces =
          std::max({norms.forces,
                    r.linfty_norm(),
                    analysis.get_internal_forces()[m].linfty_norm()});
        r -= analysis.get_internal_forces()[m];
        mode.condense(r);
        norms.max = std::max(norms.max, r.linfty_norm());
        norms.l2 += r.norm_sqr();
        condensed = stress_excess[m];
        mode.condense(condensed);
        norms.body_loads = std::max(norms.body_loads, condensed.linfty_norm());
      }
    norms.l2 = std::sqrt(norms.l2);
    return norms;
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::predict(const double target)
  {
    const double dlambda = target - analysis.accepted_load_factor();
    const double scale   = accepted_step != 0 ? dlambda / accepted_step : 0;
    if (scale > 0)
      {
        for (unsigned int m = 0; m < analysis.n_modes(); ++m)
          {
            ModeVector &increment = analysis.get_step_increment()[m];
            increment             = accepted_increment[m];
            increment *= scale;
          }
        return;
      }
    // The first step, or a reversal of the load: no secant predictor. The
    // prescribed displacements of the step are carried into the body by
    // its elastic response to them alone, dlambda (u_p - K^-1 K u_p) (the
    // loads are left to the first correction, as before). Moving only the
    // constrained DoFs would put a pile's or a footing's whole displacement
    // into the one row of cells beside it: a thin layer there is sheared by
    // u / t, far beyond yield even where the step is elastic, and the
    // iterations have to bring it back from there (on a layer that follows
    // a circle, and so can slide round it, they often could not).
    ModeVectors &increments = analysis.get_step_increment();
    double       prescribed = 0;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const ModeSystem &mode = analysis.get_mode_system(m);
        prescribed =
          std::max(prescribed, mode.unit_prescribed_displacement.linfty_norm());
      }
    const bool lift = prescribed > 0 && dlambda != 0;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const ModeSystem &mode = analysis.get_mode_system(m);
        if (lift)
          {
            // -K u_p: the right-hand side f - K u_p less f.
            increments[m] = mode.unit_rhs;
            increments[m] -= mode.unit_load;
            increments[m] *= dlambda;
            mode.condense(increments[m]);
          }
        else
          increments[m] = 0;
      }
    if (lift)
      analysis.elastic_solve(increments);
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        const ModeSystem &mode = analysis.get_mode_system(m);
        if (lift)
          mode.distribute(increments[m]);
        increments[m].add(dlambda, mode.unit_prescribed_displacement);
      }
  }


  template <int dim>
  unsigned int
  ReturnMappingMethod<dim>::max_iterations() const
  {
    return parameters.max_iterations;
  }


  template <int dim>
  unsigned int
  ReturnMappingMethod<dim>::max_cut_backs() const
  {
    return 0;
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::start_attempt()
  {}


  template <int dim>
  bool
  ReturnMappingMethod<dim>::gives_up(const ConvergenceWatch &) const
  {
    return false;
  }


  template <int dim>
  StepResult
  ReturnMappingMethod<dim>::solve_step(const double new_load_factor)
  {
    StepResult result{0, false, 0, 0};
    // Under work control the argument is the step's work, and the step is
    // one attempt: the stepping halves the work of one that fails.
    if (work_control)
      {
        step_work          = new_load_factor;
        result.converged   = attempt(new_load_factor, result);
        result.load_factor = load_factor_now;
        result.work        = work_of(analysis.get_step_increment());
        return result;
      }
    SubStepping parts(analysis.accepted_load_factor(),
                      new_load_factor,
                      max_cut_backs());
    while (true)
      {
        const double            target = parts.target();
        const SubStepping::Next next   = parts.report(attempt(target, result));
        result.cut_backs               = parts.cut_backs();
        if (next == SubStepping::Next::done)
          {
            result.converged = true;
            break;
          }
        if (next == SubStepping::Next::failed)
          break; // the last attempt's state is kept
        if (next == SubStepping::Next::next_part)
          {
            analysis.accept_step(target);
            this->acceptance_listener->state_accepted();
          }
        else
          this->state_rejected();
      }
    result.work = work_of(analysis.get_step_increment());
    return result;
  }


  template <int dim>
  bool
  ReturnMappingMethod<dim>::attempt(const double target, StepResult &result)
  {
    if (work_control)
      predict_by_work();
    else
      {
        predict(target);
        load_factor_now = target;
      }
    start_attempt();

    ResidualNorms norms = starting_residual(load_factor_now);
    watch.start();
    for (unsigned int k = 0; k < max_iterations(); ++k)
      {
        if (interrupted())
          return false;
        ++result.iterations;
        if (!iterate(load_factor_now, norms, result))
          return false;
        result.plastic_points = norms.n_yielding;
        if (converged(norms))
          return true;
        report_iteration(k + 1, "residual", norms.max / norms.forces);
        growth.iteration_done(k + 1,
                              max_iterations(),
                              analysis.get_step_increment());
        watch.add(norms.max / norms.forces);
        if (!this->final_attempt && gives_up(watch))
          return false;
      }
    result.growth_ratio = growth.growth_ratio(analysis.get_step_increment());
    return false;
  }


  template <int dim>
  bool
  ReturnMappingMethod<dim>::converged(const ResidualNorms &norms)
  {
    using Criterion        = SolverParameters::ConvergenceCriterion;
    const double tolerance = parameters.tolerance;
    // Round-off: also of the forces the step started from, where the
    // target state carries none (a phase that unloads the body).
    if (norms.max <= 1e-10 * std::max(norms.forces, norms.start_forces))
      return true;
    switch (parameters.convergence_criterion)
      {
        case Criterion::body_loads:
          return norms.max <= tolerance * norms.body_loads;
        case Criterion::residual:
          return norms.max <= tolerance * norms.forces;
          case Criterion::displacements: {
            double change = 0, size = 0;
            for (unsigned int m = 0; m < analysis.n_modes(); ++m)
              {
                const ModeVector &increment = analysis.get_step_increment()[m];
                previous_increment[m] -= increment;
                change = std::max(change, previous_increment[m].linfty_norm());
                size   = std::max(size, increment.linfty_norm());
              }
            return change <= tolerance * size;
          }
      }
    return false;
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::elastic_corrections()
  {
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      correction[m] = residual[m];
    analysis.elastic_solve(correction);
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      analysis.get_mode_system(m).distribute(correction[m]);
  }


  template <int dim>
  void
  ReturnMappingMethod<dim>::remember_increments()
  {
    previous_increment = analysis.get_step_increment();
  }


  template class ReturnMappingMethod<2>;
  template class ReturnMappingMethod<3>;
} // namespace thinlayer
