#include <thinlayer/base/interruption.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/output/output_writer.h>
#include <thinlayer/postprocess/layer_profile.h>
#include <thinlayer/postprocess/monitors.h>
#include <thinlayer/solution_methods/step_progress.h>
#include <thinlayer/stepping/programme.h>

#include <cmath>
#include <limits>

namespace thinlayer
{
  namespace
  {
    using text_format::printf;

    /// One line of progress on screen for an attempt, as it ends. A failed
    /// step's state is no equilibrium, and its numbers depend on rounding:
    /// they go to history.csv (where the mechanism can be seen), not here.
    /// Under work control (@p from_load_factor finite) a failed attempt's
    /// load factor is such a number too: the line names the accepted load
    /// factor the step started from instead.
    void
    print_attempt(const unsigned int       step,
                  const double             load_factor,
                  const double             from_load_factor,
                  const double             load,
                  const double             displacement,
                  const StepResult        &result,
                  const bool               on_plateau,
                  const bool               doubled,
                  const LoadStepping::Next next,
                  const bool               probe,
                  const bool               print_iterations,
                  std::ostream            &out)
    {
      const bool from = !result.converged && std::isfinite(from_load_factor);
      out << "  step " << printf("%4.0f", step)
          << (from ? "  from load factor " : "  load factor ")
          << printf("%10.4g", from ? from_load_factor : load_factor);
      if (result.converged && next == LoadStepping::Next::retry)
        out << (on_plateau ? "  converged on the plateau of the load"
                : doubled  ? "  converged, more than doubling the "
                             "displacement"
                           : "  converged") +
                 std::string(": cut back (its state is in history.csv)");
      else if (result.converged && next != LoadStepping::Next::retry &&
               next != LoadStepping::Next::stop)
        out << "  load " << printf("%12.5e", load) << "  displacement "
            << printf("%12.5e", displacement)
            << (print_iterations
                  ? "  iterations " + printf("%4.0f", result.iterations)
                  : std::string())
            << (on_plateau ? "  converged, on the plateau" : "  converged");
      else if (result.converged && probe)
        out << "  probe beyond the failed step: converged (not accepted)";
      else if (result.converged)
        out << "  converged against its load: not accepted";
      else if (result.outside_surface)
        out << "  met the test with stresses outside the yield surface "
               "(round-off): "
            << (next == LoadStepping::Next::retry
                  ? "cut back (its state is in history.csv)"
                  : "FAILED");
      else if (next == LoadStepping::Next::retry)
        out << "  failed: cut back (its state is in history.csv)";
      else if (result.non_finite)
        out << "  FAILED: not a finite number";
      else if (probe)
        out << "  probe beyond the failed step: FAILED to converge";
      else
        out << "  FAILED to converge (its state is in history.csv)";
      out << std::endl;
    }
  } // namespace


  template <int dim>
  ProgrammeResult
  Programme<dim>::run()
  {
    result.displacement_offset = phase.displacement_offset;
    // A strength reduction starts from the state of the phase before it,
    // converged at F = 1: the lower end of its bracket.
    if (phase.strength_reduction)
      {
        result.last_converged_load = 1;
        result.load_factor_origin  = 1;
      }
    // Under work control the programme's first step alone is taken by
    // its load factor; run_by_work() goes on from its state.
    const bool by_work = loading.control == LoadingParameters::Control::work;
    LoadingParameters first_step = loading;
    if (by_work)
      first_step.load_increments = {loading.load_increments.front()};
    // An easy step: at most a quarter of the constant-stiffness
    // iteration limit (Newton's steps take a few iterations each).
    LoadStepping stepping(by_work ? first_step : loading,
                          p.solver.continue_after_failure,
                          easy_iterations());
    while (!stepping.finished())
      {
        const Attempt a = attempt(phase.steps_before + stepping.step(),
                                  stepping.target(),
                                  stepping.failure_is_final());
        // A signal stopped the step: it is neither a failure nor a
        // result, so it is not recorded; the accepted steps are the run.
        if (interrupted())
          {
            result.interrupted_by          = interruption_signal();
            result.interrupted_load_factor = a.load_factor;
            solver.reject();
            break;
          }
        // Under load, a step longer than the collapse resolution that
        // lands on the plateau, or whose displacement grows more than
        // twice as much as its load, is cut back like a failed one: the
        // plateau may begin within it, and it is judged over a doubling of
        // the displacement, so the curve wants a state at least every
        // doubling there. (Under prescribed displacement the load hardly
        // changes along the plateau: the programme goes on.)
        const bool loaded = under_load();
        const bool plateau_cut =
          (a.on_plateau || a.doubled) && loaded && !stepping.failure_is_final();
        StepResult reported           = a.result;
        reported.converged            = a.result.converged && !plateau_cut;
        const LoadStepping::Next next = stepping.report(reported);
        record(a, next);
        if (next == LoadStepping::Next::retry)
          {
            solver.reject();
            continue;
          }
        ++result.steps_run;
        if (reported.converged)
          {
            accept(a);
            // The load has levelled off to the resolution: the collapse
            // load, reached.
            if (a.on_plateau && loaded)
              {
                result.stopped            = true;
                result.stopped_on_plateau = true;
                result.bracket_resolved   = true;
                break;
              }
            continue;
          }
        // Non-convergence is a result, not an error.
        if (result.converged)
          result.first_failed_load = a.load;
        result.converged = false;
        if (next == LoadStepping::Next::accept_failed)
          {
            solver.accept();
            continue;
          }
        result.stopped            = true;
        result.against_load       = a.against_load;
        result.non_finite         = a.result.non_finite;
        result.failed_load_factor = a.load_factor;
        result.bracket_resolved   = stepping.automatic() && bracket_resolved(a);
        result.stiffness_ratio    = a.stiffness_ratio;
        result.growth_ratio       = a.result.growth_ratio;
        if (stepping.automatic() && !a.result.non_finite && !a.against_load &&
            under_load() &&
            !shows_mechanism(a.stiffness_ratio, a.result.growth_ratio))
          probe_beyond(a);
        break;
      }
    if (by_work && stepping.finished() && !result.stopped &&
        result.interrupted_by == 0)
      run_by_work();
    // A run that stops on a failure holds that attempt's state.
    write_last_state(result.stopped && !result.stopped_on_plateau);
    return result;
  }


  template <int dim>
  unsigned int
  Programme<dim>::easy_iterations() const
  {
    // Under work control every step is Newton's.
    return (result.by_work ? p.solver.max_newton_iterations
                           : p.solver.max_iterations) /
           4;
  }


  template <int dim>
  void
  Programme<dim>::run_by_work()
  {
    constexpr double doubling_margin = 0.05;
    double           end             = 0;
    for (const double d : loading.load_increments)
      end += d;
    solver.set_work_control(true);
    result.by_work = true;
    // The first step's work sets the scale; the work at most doubles per
    // step, so that the plateau rule, judged over a doubling of the
    // displacement, has a state at least every doubling.
    double step = accepted_work;
    // The loads did positive work on the first step's elastic-plastic
    // increment (f^T K^-1 f > 0): the setup refused loadings without loads.
    AssertThrow(accepted_work > 0 && std::isfinite(accepted_work),
                ExcMessage("Work control found no positive work of the "
                           "loads on the programme's first step."));
    while (true)
      {
        // Up to a little more than the work done so far: along the
        // plateau the displacement grows with the work, and a step that
        // doubles both exactly leaves the doubling to round-off.
        step = std::min(step, (1 + doubling_margin) * accepted_work);
        const bool final = step <= loading.collapse_resolution * accepted_work;
        const Attempt a =
          attempt(phase.steps_before + result.steps_run + 1, step, final);
        if (interrupted())
          {
            result.interrupted_by          = interruption_signal();
            result.interrupted_load_factor = a.load_factor;
            solver.reject();
            break;
          }
        const LoadStepping::Next next = a.result.converged
                                          ? LoadStepping::Next::accept
                                        : final ? LoadStepping::Next::stop
                                                : LoadStepping::Next::retry;
        record(a, next);
        if (next == LoadStepping::Next::retry)
          {
            solver.reject();
            step /= 2;
            continue;
          }
        ++result.steps_run;
        if (a.result.converged)
          {
            accept(a);
            if (a.on_plateau)
              {
                result.stopped            = true;
                result.stopped_on_plateau = true;
                result.bracket_resolved   = true;
                break;
              }
            // The load the programme ends at, reached without a collapse.
            if (std::abs(a.load_factor) >= std::abs(end) * (1 - 1e-12))
              break;
            if (a.result.iterations <= easy_iterations())
              step *= 2;
            else if (a.result.iterations > 2 * easy_iterations())
              step /= 2;
            continue;
          }
        // A step of the resolution's work that fails: no bracket of the
        // load factor (the steps never asked for one), a failure.
        if (result.converged)
          result.first_failed_load = a.load;
        result.converged          = false;
        result.stopped            = true;
        result.against_load       = a.against_load;
        result.non_finite         = a.result.non_finite;
        result.failed_load_factor = a.load_factor;
        result.bracket_resolved   = false;
        result.stiffness_ratio    = a.stiffness_ratio;
        result.growth_ratio       = a.result.growth_ratio;
        break;
      }
    solver.set_work_control(false);
  }


  template <int dim>
  bool
  Programme<dim>::bracket_resolved(const Attempt &failed) const
  {
    const double resolution = (1 + 1e-9) * loading.collapse_resolution;
    // The phase's load at both ends (a strength reduction's F = 1 + load
    // factor), the bracket's width against the larger.
    const double origin  = phase.strength_reduction ? 1 : 0;
    const double reached = origin + result.last_converged_load_factor;
    const double beyond  = origin + failed.load_factor;
    if (result.any_step_converged || reached != 0)
      return std::abs(beyond - reached) <=
             resolution * std::max(std::abs(beyond), std::abs(reached));
    // No state converged, and the bracket is [0, beyond]: a collapse at 0
    // is bracketed only where the body's strength has no scale, so that a
    // step that fails at a fraction of the programme's first step fails at
    // every fraction of it (a cohesionless interface sliding under any
    // load). Elsewhere the halving merely ran out before the load came
    // down to the collapse load.
    return strength_has_no_scale() &&
           std::abs(beyond) <=
             resolution * std::abs(loading.load_increments.front());
  }


  template <int dim>
  bool
  Programme<dim>::strength_has_no_scale() const
  {
    if (phase.steps_before > 0 ||
        p.initial_state.procedure != InitialStateParameters::Procedure::none)
      return false;
    for (const auto &[id, material] : p.materials)
      if (material.unit_weight > 0 ||
          (material.yield_criterion != YieldCriterion::elastic &&
           material.cohesion > 0))
        return false;
    for (const auto &[id, curve] : p.interface_elements)
      if (curve.criterion != InterfaceElementParameters::Criterion::elastic &&
          (curve.adhesion > 0 || (std::isfinite(curve.tensile_strength) &&
                                  curve.tensile_strength > 0)))
        return false;
    return true;
  }


  template <int dim>
  bool
  Programme<dim>::under_load() const
  {
    return phase.strength_reduction || analysis.has_external_load();
  }


  template <int dim>
  typename Programme<dim>::Attempt
  Programme<dim>::attempt(const unsigned int step,
                          const double       load_factor,
                          const bool         final)
  {
    Attempt a{step,
              load_factor,
              {},
              0,
              0,
              false,
              std::numeric_limits<double>::quiet_NaN(),
              false,
              false,
              false};
    {
      TimerOutput::Scope scope(timer, "load steps");
      // Under work control the load factor is found by the step: the
      // accepted one is shown while it runs.
      const StepProgress progress(out,
                                  step,
                                  result.by_work
                                    ? analysis.accepted_load_factor()
                                    : load_factor,
                                  p.output.progress_interval);
      if (phase.strength_reduction)
        analysis.reduce_strength(1 + load_factor);
      a.result      = solver.solve(load_factor, final);
      a.load_factor = a.result.load_factor;
      a.load = phase.strength_reduction ? 1 + load_factor : monitors.load();
      result.displacement = monitors.displacement();
    }
    if (!std::isfinite(a.load) || !std::isfinite(result.displacement.mean))
      {
        a.result.non_finite = true;
        a.result.converged  = false;
      }
    result.total_iterations += a.result.iterations;
    ++result.attempts;
    a.stiffness_ratio = analysis.secant_stiffness_ratio();
    // A state that does negative work on its load increment is no
    // response of an elastic-plastic body (Drucker's stability): the
    // iterations have found a spurious equilibrium (seen with the
    // default method on Case 3's layer at aspect ratio 10000, at
    // displacements 1e9 times the elastic ones). It is a failed attempt.
    // Under work control the work on the increment is positive by
    // construction, and on a perfectly plastic plateau the load factor
    // stays where it is to round-off, either way: only a fall beyond the
    // collapse resolution is against the load there.
    const double against = result.by_work ? -loading.collapse_resolution : 0.;
    if (a.result.converged && under_load() && a.stiffness_ratio < against)
      {
        a.result.converged = false;
        a.against_load     = true;
      }
    const double displacement = result.displacement.mean;
    const double offset       = phase.displacement_offset;
    if (a.result.converged)
      a.rise = plateau_rise(result.curve, displacement, a.load, offset);
    const bool automatic = loading.collapse_resolution > 0;
    a.on_mechanism       = a.result.converged && automatic && under_load() &&
                     a.stiffness_ratio >= 0 &&
                     a.stiffness_ratio < mechanism_knee_ratio;
    // Under load or prescribed displacement alike; a load that falls
    // towards its limit (an active earth pressure from the at-rest one)
    // levels off as one that rises.
    a.on_plateau = a.result.converged && automatic &&
                   std::abs(a.rise) <= loading.collapse_resolution;
    // More than doubled: the displacement grew more than twice as much as
    // the load (never on a linear response).
    if (a.result.converged && automatic && !result.curve.empty())
      {
        const CurvePoint &before = result.curve.back();
        const double from = offset_displacement(before.displacement, offset);
        const double to   = offset_displacement(displacement, offset);
        a.doubled         = from * to > 0 && before.load * a.load > 0 &&
                    to / from > 2 * a.load / before.load;
      }
    return a;
  }


  template <int dim>
  void
  Programme<dim>::record(const Attempt           &a,
                         const LoadStepping::Next next,
                         const bool               probe)
  {
    {
      TimerOutput::Scope scope(timer, "output");
      writer.write_history_row({a.step,
                                result.attempts,
                                a.load_factor,
                                a.load,
                                result.displacement,
                                a.result,
                                next == LoadStepping::Next::accept ||
                                  next == LoadStepping::Next::accept_failed,
                                a.stiffness_ratio,
                                phase.name});
      // A state of the load-displacement curve: converged and accepted
      // (not a failure, nor a probe beyond one).
      const bool on_curve =
        next == LoadStepping::Next::accept && a.result.converged && !probe;
      const bool cut_back = next == LoadStepping::Next::retry;
      if (on_curve)
        ++curve_states;
      const unsigned int interval = p.output.fields_interval;
      const bool         fields =
        p.output.write_vtu &&
        (on_curve ? interval > 0 && curve_states % interval == 0
                  : !cut_back || p.output.fields_of_cut_backs);
      if (fields)
        write_fields(a.step, a.load_factor, on_curve);
      // The last accepted state's fields are written at the end if the
      // interval skipped them (write_last_state()).
      if (on_curve && !fields && p.output.write_vtu)
        unwritten_state = std::make_pair(a.step, a.load_factor);
      else if (on_curve || next == LoadStepping::Next::accept_failed)
        unwritten_state.reset();
      if (!cut_back)
        {
          writer.write_displacements(analysis, p.monitors.displacement_angle);
          writer.write_interface_profiles(a.step,
                                          a.load_factor,
                                          on_curve,
                                          analysis,
                                          layers,
                                          p.output.write_vtu);
        }
    }
    print_attempt(a.step,
                  a.load_factor,
                  result.by_work ? analysis.accepted_load_factor()
                                 : std::numeric_limits<double>::quiet_NaN(),
                  a.load,
                  result.displacement.mean,
                  a.result,
                  a.on_plateau,
                  a.doubled,
                  next,
                  probe,
                  p.output.print_iterations,
                  out);
  }


  template <int dim>
  void
  Programme<dim>::write_fields(const unsigned int step,
                               const double       load_factor,
                               const bool         on_curve)
  {
    writer.write_fields(step,
                        load_factor,
                        on_curve,
                        analysis,
                        p.monitors.displacement_angle,
                        layers);
    // A revolved view is of a Fourier body, whose mesh is 2D.
    if constexpr (dim == 2)
      if (p.output.view_slices > 0)
        writer.write_revolved_view(
          step, load_factor, on_curve, analysis, p.output.view_slices);
  }


  template <int dim>
  void
  Programme<dim>::write_last_state(const bool pending_failure)
  {
    if (!unwritten_state)
      return;
    TimerOutput::Scope scope(timer, "output");
    // Back from the failed attempt to the last accepted state, which the
    // fields show.
    if (pending_failure)
      solver.reject();
    write_fields(unwritten_state->first, unwritten_state->second, true);
    unwritten_state.reset();
  }


  template <int dim>
  void
  Programme<dim>::accept(const Attempt &a)
  {
    // A step under work control on the plateau may leave the load factor
    // where it was: its stiffness is then the last one.
    const double stiffness =
      a.load_factor != result.last_converged_load_factor
        ? (a.load - result.last_converged_load) /
            (a.load_factor - result.last_converged_load_factor)
        : result.last_stiffness;
    if (!result.any_step_converged)
      result.first_stiffness = stiffness;
    if (a.on_mechanism && !result.knee_passed && result.any_step_converged)
      {
        result.knee_passed = true;
        result.knee_load   = result.last_converged_load;
      }
    if (a.on_plateau && !std::isfinite(result.plateau_load))
      {
        result.plateau_load         = a.load;
        result.plateau_load_factor  = a.load_factor;
        result.plateau_displacement = result.displacement.mean;
        result.plateau_rise         = a.rise;
        result.plateau_from_displacement =
          state_at_half(result.curve,
                        result.displacement.mean,
                        phase.displacement_offset)
            ->displacement;
      }
    result.curve.push_back({result.displacement.mean, a.load});
    result.last_stiffness             = stiffness;
    result.last_converged_load        = a.load;
    result.last_converged_load_factor = a.load_factor;
    result.converged_displacement     = result.displacement;
    result.converged_iterations       = result.total_iterations;
    result.any_step_converged         = true;
    if (std::isfinite(a.result.work))
      accepted_work += a.result.work;
    if (a.result.max_yield_ratio > 10 * p.solver.tolerance)
      ++result.steps_with_drift;
    solver.accept();
  }


  template <int dim>
  void
  Programme<dim>::probe_beyond(const Attempt &failed)
  {
    solver.reject();
    const double probe_load_factor =
      failed.load_factor +
      (failed.load_factor - result.last_converged_load_factor);
    const Attempt probe =
      attempt(failed.step + 1, probe_load_factor, /*final=*/true);
    record(probe, LoadStepping::Next::stop, true);
    if ((!probe.result.converged || probe.on_mechanism) &&
        shows_mechanism(probe.stiffness_ratio, probe.result.growth_ratio))
      {
        result.stopped_on_mechanism = probe.on_mechanism;
        result.probe_load_factor    = probe_load_factor;
        result.stiffness_ratio      = probe.stiffness_ratio;
        result.growth_ratio         = probe.result.growth_ratio;
      }
  }

  template class Programme<2>;
  template class Programme<3>;
} // namespace thinlayer
