// Truths checked for the judgement of how a run ended (judge_outcome()),
// on programme results made up to sit on either side of each threshold of
// run_outcome.h:
// 1. A signal gives "interrupted" and no collapse load.
// 2. A programme that ran through is "completed"; under prescribed
//    displacement its last load is a plateau (a collapse load) when the
//    last step's stiffness is at most plateau_stiffness_ratio of the
//    first's (not at twice that) and the load rose by at most
//    plateau_fallback_rise over the last doubling of the displacement (not
//    by twice that, nor where no state lies at half the displacement).
// 3. A failed step is a collapse only under load, with a finite state,
//    after a converged step (or a resolved bracket), and with a mechanism
//    as evidence: secant stiffness below mechanism_stiffness_ratio (not at
//    it), or growth at least mechanism_growth_ratio (not just below). The
//    collapse load is then the last converged load, and the reason names
//    the bracket (the probe's load factor where a probe showed it).
// 4. The plateau: plateau_rise() is the load's rise over a doubling of
//    the displacement, measured from the latest state at or below half of
//    it; on a hyperbola L = d / (d + 1) it is the fraction 1 - L of the
//    limit still to come, 0 for a load that stayed, negative for one that
//    fell, and NaN where no state of the same sign lies at or below half.
//    A run stopped on the plateau under load is a collapse at the plateau
//    load, the reason naming the hyperbola's limit L / (1 - rise); under
//    prescribed displacement the first plateau state's load is the
//    collapse load of a completed run, whatever the programme's last step
//    did; the knee is reported beside a collapse.
// 5. Drift: under prescribed displacement a run with accepted steps
//    outside the yield surface (steps_with_drift > 0; one is enough)
//    claims no plateau, its load being read off those states, and says
//    why; under load the collapse load is the applied load, which drift
//    does not change, and stands.
#include <thinlayer/stepping/run_outcome.h>

#include <cmath>
#include <csignal>
#include <iostream>
#include <string>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  /// A run under load that converged up to load factor 1.2 (load 2.4)
  /// and stopped at 1.25 with the given evidence.
  ProgrammeResult
  stopped(const double stiffness_ratio, const double growth_ratio)
  {
    ProgrammeResult run;
    run.converged                  = false;
    run.any_step_converged         = true;
    run.last_converged_load        = 2.4;
    run.last_converged_load_factor = 1.2;
    run.stopped                    = true;
    run.bracket_resolved           = true;
    run.failed_load_factor         = 1.25;
    run.stiffness_ratio            = stiffness_ratio;
    run.growth_ratio               = growth_ratio;
    return run;
  }


  RunSummary
  judge(const bool under_load, const ProgrammeResult &run)
  {
    RunSummary summary;
    summary.collapse_load = std::numeric_limits<double>::quiet_NaN();
    judge_outcome(under_load, run, summary);
    std::cout << "  " << summary.outcome << ": " << summary.reason << '\n';
    return summary;
  }


  bool
  is(const RunSummary &s, const std::string &outcome, const double load)
  {
    return s.outcome == outcome &&
           (std::isnan(load) ? std::isnan(s.collapse_load)
                             : s.collapse_load == load);
  }

  const double none = std::numeric_limits<double>::quiet_NaN();
} // namespace


int
main()
{
  std::cout << "1. Interrupted\n";
  {
    ProgrammeResult run;
    run.interrupted_by          = SIGINT;
    run.interrupted_load_factor = 0.5;
    const RunSummary s          = judge(true, run);
    expect(is(s, "interrupted", none) &&
             s.reason.find("SIGINT") != std::string::npos,
           "interrupted by SIGINT, no collapse load");
  }

  std::cout << "2. Ran through\n";
  {
    ProgrammeResult run;
    run.last_converged_load = 3.0;
    run.first_stiffness     = 100;
    run.last_stiffness      = plateau_stiffness_ratio * 100;
    run.curve = {{1, 3.0 / (1 + 0.99 * plateau_fallback_rise)}, {2, 3.0}};
    expect(is(judge(true, run), "completed", none), "under load: completed");
    expect(is(judge(false, run), "completed", 3.0),
           "displacement-driven, last stiffness at the plateau ratio and "
           "the rise over the last doubling just below the fallback's: the "
           "plateau 3 is the collapse load");
    run.curve = {{1, 3.0 / (1 + 2 * plateau_fallback_rise)}, {2, 3.0}};
    const RunSummary rising = judge(false, run);
    expect(is(rising, "completed", none) &&
             rising.reason.find("no plateau is claimed") != std::string::npos,
           "the load rising by twice the fallback's rise: no plateau, and "
           "the reason says so");
    run.curve = {{1.5, 2.9}, {2, 3.0}};
    expect(is(judge(false, run), "completed", none),
           "no state at half the displacement: no plateau");
    run.curve          = {{1, 3.0}, {2, 3.0}};
    run.last_stiffness = 2 * plateau_stiffness_ratio * 100;
    expect(is(judge(false, run), "completed", none),
           "at twice the ratio: no plateau");
  }

  std::cout << "3. A failed step\n";
  {
    const double below = 0.5 * mechanism_stiffness_ratio;
    expect(is(judge(true, stopped(below, none)), "collapse", 2.4),
           "stiffness below the mechanism ratio: collapse at 2.4");
    expect(is(judge(true, stopped(mechanism_stiffness_ratio, none)),
              "not converged",
              none),
           "stiffness at the ratio: no mechanism");
    expect(is(judge(true, stopped(0.5, mechanism_growth_ratio)),
              "collapse",
              2.4),
           "growth at the growth ratio: collapse");
    expect(is(judge(true, stopped(0.5, 0.99 * mechanism_growth_ratio)),
              "not converged",
              none),
           "growth just below it: no mechanism");
    expect(is(judge(false, stopped(below, none)), "not converged", none),
           "under prescribed displacement: never a collapse");

    ProgrammeResult run = stopped(below, none);
    run.non_finite      = true;
    expect(is(judge(true, run), "not converged", none),
           "not finite: never a collapse");
    run              = stopped(below, none);
    run.against_load = true;
    expect(is(judge(true, run), "not converged", none),
           "against its load: never a collapse");
    run                    = stopped(below, none);
    run.any_step_converged = false;
    run.bracket_resolved   = false;
    expect(is(judge(true, run), "not converged", none),
           "the first step failed, no bracket: no collapse load");
    run.bracket_resolved = true;
    expect(is(judge(true, run), "collapse", 2.4),
           "the first step failed within a resolved bracket: collapse");

    run                   = stopped(below, none);
    run.probe_load_factor = 1.3;
    const RunSummary s    = judge(true, run);
    expect(is(s, "collapse", 2.4) &&
             s.reason.find("between 1.2 and 1.3") != std::string::npos,
           "shown by a probe: the bracket reaches the probe");
  }

  std::cout << "4. The plateau\n";
  {
    const auto hyperbola = [](const double d) { return d / (d + 1); };
    bool       exact     = true;
    for (const double d : {0.1, 1.0, 10.0, 200.0})
      {
        // States at a quarter, at half and just beyond half of d: the
        // rise is measured from half.
        const std::vector<CurvePoint> states = {{d / 4, hyperbola(d / 4)},
                                                {d / 2, hyperbola(d / 2)},
                                                {0.6 * d, hyperbola(0.6 * d)}};
        exact = exact && std::abs(plateau_rise(states, d, hyperbola(d)) -
                                  (1 - hyperbola(d))) < 1e-12;
      }
    expect(exact, "on a hyperbola the rise is the fraction still to come");
    const std::vector<CurvePoint> curve = {{1, 2}, {3, 2.5}};
    expect(plateau_rise(curve, 2, 2) == 0, "a load that stayed: rise 0");
    expect(plateau_rise(curve, 2, 1.9) < 0, "a load that fell: negative");
    expect(std::isnan(plateau_rise(curve, 1.5, 2)) &&
             std::isnan(plateau_rise(curve, -2, 2)) &&
             std::isnan(plateau_rise({}, 2, 2)),
           "no state at or below half, one of another sign, or none: NaN");

    ProgrammeResult run;
    run.converged                  = true;
    run.any_step_converged         = true;
    run.stopped                    = true;
    run.stopped_on_plateau         = true;
    run.bracket_resolved           = true;
    run.last_converged_load        = 2.5;
    run.last_converged_load_factor = 1.25;
    run.plateau_load               = 2.5;
    run.plateau_load_factor        = 1.25;
    run.plateau_displacement       = 8;
    run.plateau_from_displacement  = 3.5;
    run.plateau_rise               = 0.004;
    run.knee_load                  = 2.3;
    RunSummary s                   = judge(true, run);
    expect(is(s, "collapse", 2.5) &&
             s.reason.find("between 2.5 and 2.51004") != std::string::npos &&
             s.knee_load == 2.3 &&
             s.reason.find("after the load 2.3") != std::string::npos,
           "under load, on the plateau: collapse at its load, the "
           "hyperbola's limit and the knee named");

    run.stopped             = false;
    run.stopped_on_plateau  = false;
    run.last_converged_load = 2.7;
    run.first_stiffness     = 100;
    run.last_stiffness      = 50;
    expect(is(judge(false, run), "completed", 2.5),
           "under prescribed displacement: the first plateau state's load, "
           "though the last step still rose");

    std::cout << "5. drift\n";
    run.steps_with_drift = 1;
    s                    = judge(false, run);
    expect(is(s, "completed", none) &&
             s.reason.find("no plateau is claimed: 1 accepted step") !=
               std::string::npos,
           "a plateau of a run with drift is no collapse load");
    run.stopped            = true;
    run.stopped_on_plateau = true;
    expect(is(judge(true, run), "collapse", 2.5),
           "under load, the collapse at the applied load stands");
  }
  return truths::conclude();
}
