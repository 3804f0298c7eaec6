#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/output/output_writer.h>
#include <thinlayer/postprocess/layer_profile.h>
#include <thinlayer/postprocess/monitors.h>
#include <thinlayer/stepping/phases.h>
#include <thinlayer/stepping/programme.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  template <int dim>
  Phases<dim>::Phases(const Parameters                     &p,
                      StepAccess<dim>                      &analysis,
                      StepSolver<dim>                      &solver,
                      const Monitors<dim>                  &monitors,
                      const std::vector<LayerProfile<dim>> &layers,
                      TimerOutput                          &timer,
                      std::ostream                         &out)
    : p(p)
    , analysis(analysis)
    , solver(solver)
    , monitors(monitors)
    , layers(layers)
    , timer(timer)
    , out(out)
  {}


  template <int dim>
  bool
  Phases<dim>::loading_runs() const
  {
    return p.initial_state.procedure ==
             InitialStateParameters::Procedure::none ||
           analysis.applies_anything(PhaseLoads::boundaries);
  }


  template <int dim>
  void
  Phases<dim>::prepare(RunSummary &summary)
  {
    using Procedure      = InitialStateParameters::Procedure;
    const auto procedure = p.initial_state.procedure;
    summary.initial_state =
      InitialStateParameters::procedure_names.name(procedure);
    if (!loading_runs() && !p.strength_reduction.active())
      throw InputError(p.parameter_file,
                       "Boundary <id>",
                       "the loading after the initial state applies nothing: "
                       "every traction, pressure and prescribed displacement "
                       "is 0 (the weight is the initial state's); expected "
                       "at least one that is not, or a Strength reduction");
    for (unsigned int k = 0; k < p.loading_phases.size(); ++k)
      if (!analysis.applies_anything(PhaseLoads::boundaries, k + 1))
        throw InputError(p.parameter_file,
                         LoadingPhaseParameters::section(k + 2) +
                           "/Boundary <id>",
                         "the phase applies nothing: every traction, "
                         "pressure and prescribed displacement it gives is "
                         "0; expected at least one that is not");
    if (procedure == Procedure::k0)
      {
        summary.initial_out_of_balance = analysis.set_initial_stresses();
        summary.initial_state_outcome  = "set";
        summary.initial_state_reason =
          "the at-rest stresses of the weight, out of balance by " +
          text_format::printf("%.2e", summary.initial_out_of_balance) +
          " of the largest nodal weight";
        PhaseSummary initial;
        initial.name    = "initial state";
        initial.outcome = summary.initial_state_outcome;
        initial.reason  = summary.initial_state_reason;
        summary.phases.push_back(initial);
      }
  }


  template <int dim>
  void
  Phases<dim>::judge(const ProgrammeResult &result,
                     const bool             under_load,
                     RunSummary            &summary) const
  {
    // Each phase is judged on its own, and listed with its outcome.
    judge_outcome(under_load, result, summary);
    PhaseSummary phase;
    phase.name                = summary.phase;
    phase.outcome             = summary.outcome;
    phase.reason              = summary.reason;
    phase.load_steps          = result.steps_run;
    phase.collapse_load       = summary.collapse_load;
    phase.last_converged_load = result.last_converged_load;
    phase.final_displacement  = result.any_step_converged
                                  ? result.converged_displacement.mean
                                  : std::numeric_limits<double>::quiet_NaN();
    summary.phases.push_back(phase);
  }


  template <int dim>
  double
  Phases<dim>::elastic_displacement_of_carried_loads()
  {
    // The accepted state's internal forces balance what it carries (its
    // reactions vanish as the constraints are condensed).
    ModeVectors u = analysis.new_mode_vectors();
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        u[m] = analysis.get_internal_forces()[m];
        analysis.get_mode_system(m).condense(u[m]);
      }
    analysis.elastic_solve(u);
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      {
        analysis.get_mode_system(m).distribute(u[m]);
        u[m].update_ghost_values();
      }
    return monitors.displacement_of(u).mean;
  }


  template <int dim>
  ProgrammeResult
  Phases<dim>::run(OutputWriter &writer, RunSummary &summary)
  {
    using Procedure      = InitialStateParameters::Procedure;
    using Loads          = PhaseLoads;
    const auto procedure = p.initial_state.procedure;
    const auto run_phase = [&](const Phase &phase) {
      return Programme<dim>(
               p, phase, analysis, solver, monitors, layers, writer, timer, out)
        .run();
    };
    // A phase that did not complete ends the run: its outcome is the run's.
    const auto ended = [&](const ProgrammeResult &result,
                           const std::string     &next) {
      if (summary.outcome == "completed" && result.interrupted_by == 0)
        return false;
      summary.reason = "the " + summary.phase + " did not complete, and " +
                       next + " was not run: " + summary.reason;
      return true;
    };
    unsigned int    steps = 0;
    ProgrammeResult result;

    if (procedure == Procedure::k0)
      out << "  initial state: K0 procedure, " << summary.initial_state_reason
          << std::endl;
    else if (procedure == Procedure::gravity_loading)
      {
        out << "  initial state: gravity loading" << std::endl;
        analysis.begin_phase(Loads::weight, false);
        solver.begin_phase();
        summary.phase = "initial state";
        result        = run_phase(
          {"initial state",
                  {p.initial_state.load_increments, p.loading.collapse_resolution},
                  0});
        judge(result, analysis.has_external_load(), summary);
        summary.initial_state_outcome = summary.outcome;
        summary.initial_state_reason  = summary.reason;
        summary.initial_state_steps   = result.steps_run;
        steps                         = result.steps_run;
        if (ended(result, "the loading"))
          return result;
      }

    if (loading_runs())
      {
        if (procedure != Procedure::none)
          {
            out << "  loading" << std::endl;
            analysis.begin_phase(Loads::boundaries,
                                 p.initial_state.reset_displacements);
            solver.begin_phase();
            summary.initial_load         = monitors.load();
            summary.initial_displacement = monitors.displacement().mean;
          }
        summary.phase = "loading";
        result        = run_phase({"loading", p.loading, steps});
        judge(result, analysis.has_external_load(), summary);
        steps += result.steps_run;
      }

    // Further loading phases, each from where the one before it ended.
    for (unsigned int k = 0; k < p.loading_phases.size(); ++k)
      {
        const LoadingPhaseParameters &phase = p.loading_phases[k];
        if (steps > 0 && ended(result, phase.name))
          return result;
        out << "  " << phase.name << std::endl;
        analysis.begin_phase(Loads::boundaries, false, k + 1);
        solver.begin_phase();
        summary.phase                = phase.name;
        summary.initial_load         = monitors.load();
        summary.initial_displacement = monitors.displacement().mean;
        result = run_phase({phase.name, phase.loading, steps});
        judge(result, analysis.has_external_load(), summary);
        steps += result.steps_run;
      }
    if (p.strength_reduction.active() && steps > 0 &&
        ended(result, "the strength reduction"))
      return result;

    if (p.strength_reduction.active())
      {
        out << "  strength reduction" << std::endl;
        const double scale =
          std::max(std::abs(elastic_displacement_of_carried_loads()),
                   std::abs(monitors.displacement().mean));
        analysis.begin_phase(Loads::none, true);
        solver.begin_phase();
        summary.phase                = "strength reduction";
        summary.initial_load         = 1;
        summary.initial_displacement = 0;
        result                       = run_phase({"strength reduction",
                                                  {p.strength_reduction.factor_increments,
                                                   p.loading.collapse_resolution},
                                                  steps,
                                                  true,
                                                  scale});
        judge(result, true, summary);
        summary.safety_factor = summary.collapse_load;
      }
    return result;
  }


  template class Phases<2>;
  template class Phases<3>;
} // namespace thinlayer
