#include <thinlayer/base/text_format.h>
#include <thinlayer/stepping/run_outcome.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <limits>

// How a run ended: the evidence of a mechanism, and the outcome, its
// reason and the collapse load that summary.json reports.

namespace thinlayer
{
  bool
  shows_mechanism(const double stiffness_ratio, const double growth_ratio)
  {
    // Displacements ten times the elastic ones in either direction: at
    // and beyond the limit load no equilibrium is near, and where a
    // failing iterate runs depends on the method (from the secant
    // predictor it often runs against the load). A method that merely
    // diverges converges again once the step is cut: this is asked of a
    // step that failed at the collapse resolution (or, with the programme
    // as given, of the step that failed, the paper's collapse).
    return std::abs(stiffness_ratio) < mechanism_stiffness_ratio ||
           growth_ratio >= mechanism_growth_ratio;
  }


  double
  offset_displacement(const double displacement, const double offset)
  {
    return displacement < 0 ? displacement - offset : displacement + offset;
  }


  const CurvePoint *
  state_at_half(const std::vector<CurvePoint> &states,
                const double                   displacement,
                const double                   offset)
  {
    const double d = offset_displacement(displacement, offset);
    for (auto state = states.rbegin(); state != states.rend(); ++state)
      if (const double ds = offset_displacement(state->displacement, offset);
          ds * d > 0 && std::abs(ds) <= std::abs(d) / 2)
        return &*state;
    return nullptr;
  }


  double
  plateau_rise(const std::vector<CurvePoint> &states,
               const double                   displacement,
               const double                   load,
               const double                   offset)
  {
    const CurvePoint *half = state_at_half(states, displacement, offset);
    return half != nullptr && half->load * load > 0
             ? load / half->load - 1
             : std::numeric_limits<double>::quiet_NaN();
  }


  namespace
  {
    using text_format::printf;

    /// The stiffness and growth figures of the step that ended the run,
    /// in words, for the reason.
    std::string
    evidence(const ProgrammeResult &run)
    {
      // A strength reduction raises no load, so its steps have no secant
      // stiffness (NaN): only the growth of the displacement change tells.
      std::string text;
      if (std::isfinite(run.stiffness_ratio))
        text = std::string(run.stopped_on_mechanism
                             ? "the step converged, with a secant stiffness of "
                             : "the failed step's secant stiffness is ") +
               printf("%.2g", run.stiffness_ratio) + " of the elastic one";
      if (std::isfinite(run.growth_ratio))
        text += std::string(text.empty() ? "the failed step's" : ", and its") +
                " displacement change grew by a factor " +
                printf("%.3g", run.growth_ratio) +
                " over the second half of its iterations";
      return text.empty() ? "no figures of the failed step" : text;
    }

    /// Where and how the load reached its plateau.
    std::string
    plateau(const ProgrammeResult &run)
    {
      return "the load reached its plateau at " +
             std::string(run.load_factor_origin != 0
                           ? "strength reduction factor F "
                           : "load factor ") +
             printf("%.6g", run.load_factor_origin + run.plateau_load_factor) +
             ": it rose " + printf("%+.3f", 100 * run.plateau_rise) +
             "% while the displacement grew from " +
             printf("%.4g",
                    offset_displacement(run.plateau_from_displacement,
                                        run.displacement_offset)) +
             " to " +
             printf("%.4g",
                    offset_displacement(run.plateau_displacement,
                                        run.displacement_offset)) +
             (run.displacement_offset != 0
                ? " (the phase's own displacement with " +
                    printf("%.4g", run.displacement_offset) +
                    ", the scale of its growth, added)"
                : std::string()) +
             ", at least doubling (at most the collapse resolution: on a "
             "curve levelling off like a hyperbola the fraction of the limit "
             "still to come equals that rise, so the limit lies between " +
             printf("%.6g", run.plateau_load) + " and " +
             printf("%.6g",
                    run.plateau_load / (1 - std::max(0., run.plateau_rise))) +
             ")";
    }


    /// Withdraw the plateau of a run under prescribed displacement with
    /// accepted steps that drifted outside the yield surface: its load is
    /// read off those states, which are not the elastic-plastic response.
    void
    refuse_if_drift(const ProgrammeResult &run, RunSummary &s)
    {
      if (run.steps_with_drift == 0 || !std::isfinite(s.collapse_load))
        return;
      s.collapse_load      = std::numeric_limits<double>::quiet_NaN();
      const unsigned int n = run.steps_with_drift;
      s.reason += "; no plateau is claimed: " + std::to_string(n) +
                  (n == 1 ? " accepted step has" : " accepted steps have") +
                  " stresses more than 10 TOL outside the yield surface, so "
                  "the loads read off them are not the elastic-plastic "
                  "response";
    }
  } // namespace


  void
  judge_outcome(const bool             under_load,
                const ProgrammeResult &run,
                RunSummary            &s)
  {
    // A strength reduction's steps are stated by their factor F.
    const bool        reduction = run.load_factor_origin != 0;
    const std::string factor =
      reduction ? "strength reduction factor F" : "load factor";
    const auto at = [&](const double load_factor) {
      return " at " + factor + " " +
             printf("%.6g", run.load_factor_origin + load_factor);
    };
    // The figures are this phase's: none is kept from a phase before it.
    s.collapse_load = std::numeric_limits<double>::quiet_NaN();
    s.knee_load     = std::numeric_limits<double>::quiet_NaN();
    s.collapse_load_factor_bracket.clear();
    if (run.interrupted_by != 0)
      {
        s.outcome = "interrupted";
        s.reason  = std::string(run.interrupted_by == SIGINT    ? "SIGINT"
                               : run.interrupted_by == SIGTERM ? "SIGTERM"
                                                               : "a signal") +
                   " stopped the step" + at(run.interrupted_load_factor) +
                   "; the steps before it are complete";
        return;
      }
    if (!run.stopped)
      {
        s.outcome = run.converged ? "completed" : "not converged";
        s.reason  = run.converged
                      ? "every load step converged"
                      : "steps that failed were accepted (Solver/Continue "
                        "after failure)";
        if (!under_load && run.converged && std::isfinite(run.plateau_load))
          {
            s.collapse_load = run.plateau_load;
            s.reason += "; " + plateau(run);
          }
        else if (!under_load && run.converged &&
                 std::abs(run.last_stiffness) <=
                   plateau_stiffness_ratio * std::abs(run.first_stiffness))
          {
            // Levelled off less sharply than the resolution asks: the
            // load at the end of the programme, if it has stopped rising.
            const double      rise = run.curve.empty()
                                       ? std::numeric_limits<double>::quiet_NaN()
                                       : plateau_rise(run.curve,
                                                 run.curve.back().displacement,
                                                 run.curve.back().load,
                                                 run.displacement_offset);
            const std::string stiffness =
              "its last step's stiffness below " +
              printf("%g", plateau_stiffness_ratio) + " of the first step's";
            if (std::abs(rise) <= plateau_fallback_rise)
              {
                s.collapse_load = run.last_converged_load;
                s.reason += "; the load levelled off by the end (" + stiffness +
                            ", and it rose " + printf("%+.3f", 100 * rise) +
                            "% over the last doubling of the displacement), "
                            "though no state's load rise over a doubling of "
                            "the displacement fell to the collapse "
                            "resolution";
              }
            else
              s.reason += "; no plateau is claimed: " + stiffness +
                          ", but the load " +
                          (std::isfinite(rise)
                             ? "rose " + printf("%+.3f", 100 * rise) +
                                 "% over the last doubling of the "
                                 "displacement, more than " +
                                 printf("%g", 100 * plateau_fallback_rise) + "%"
                             : "has no state at half the last displacement "
                               "to tell whether it still rises");
          }
        refuse_if_drift(run, s);
        return;
      }
    s.outcome = "not converged";
    if (run.non_finite)
      s.reason = "values that are not finite numbers" +
                 at(run.failed_load_factor) +
                 " (an overflow: displacements, stresses, tractions or "
                 "their invariants beyond the range of double precision)";
    else if (run.against_load)
      s.reason = "the step" + at(run.failed_load_factor) +
                 " converged to a state moving against its load (secant "
                 "stiffness " +
                 printf("%.2g", run.stiffness_ratio) +
                 " of the elastic one): a spurious equilibrium, no response "
                 "of the body and no mechanism";
    else if (!under_load)
      s.reason = "the step failed" + at(run.failed_load_factor) +
                 " under prescribed displacement, where a failed step is "
                 "no collapse";
    else if (!run.any_step_converged && !run.bracket_resolved)
      s.reason = "the first step failed" + at(run.failed_load_factor) +
                 " and no state converged: a collapse load, if this is "
                 "one, lies somewhere below it; expected smaller first "
                 "steps (Loading/Load increments) or automatic stepping";
    else if (run.stopped_on_plateau)
      {
        s.outcome       = "collapse";
        s.collapse_load = run.plateau_load;
        s.reason        = plateau(run);
      }
    else if (run.by_work)
      s.reason =
        "a step under work control failed" + at(run.failed_load_factor) +
        " at the resolution's fraction of the work done, before the load "
        "reached its plateau: a step that prescribes work asks for no load "
        "factor, so its failure brackets no collapse (" +
        evidence(run) +
        "); where the whole body slides as a rigid mechanism (zero-thickness "
        "interface elements), its tangent is singular and only Loading/"
        "Control = load brackets the collapse";
    else if (shows_mechanism(run.stiffness_ratio, run.growth_ratio))
      {
        s.outcome         = "collapse";
        s.collapse_load   = run.last_converged_load;
        const bool probed = std::isfinite(run.probe_load_factor);
        s.reason =
          "a mechanism" +
          (probed ? " beyond the failed step" + at(run.failed_load_factor) +
                      ", shown by a probe" + at(run.probe_load_factor)
                  : at(run.failed_load_factor)) +
          ": " + evidence(run);
        s.collapse_load_factor_bracket = {
          {"low", run.load_factor_origin + run.last_converged_load_factor},
          {"high",
           run.load_factor_origin +
             (probed ? run.probe_load_factor : run.failed_load_factor)}};
        s.reason +=
          "; the " +
          std::string(reduction ? "safety factor" : "collapse load factor") +
          " lies between " +
          printf("%.6g", s.collapse_load_factor_bracket.at("low")) + " and " +
          printf("%.6g", s.collapse_load_factor_bracket.at("high"));
      }
    else
      s.reason = "the step failed" + at(run.failed_load_factor) +
                 " with no mechanism shown: " + evidence(run);
    s.knee_load = run.knee_load;
    if (s.outcome == "collapse" && std::isfinite(run.knee_load))
      s.reason += "; the knee of the curve (a step's secant stiffness below " +
                  printf("%g", mechanism_knee_ratio) +
                  " of the elastic one) came after the load " +
                  printf("%.6g", run.knee_load);
  }
} // namespace thinlayer
