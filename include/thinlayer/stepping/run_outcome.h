#ifndef thinlayer_stepping_run_outcome_h
#define thinlayer_stepping_run_outcome_h

#include <thinlayer/output/run_summary.h>
#include <thinlayer/postprocess/displacement_measure.h>

#include <limits>
#include <vector>

namespace thinlayer
{
  /**
   * A failed step under load is a collapse only with a mechanism as
   * evidence: its secant stiffness along the increment below this
   * fraction of the elastic one (and positive), i.e. displacements at
   * least ten times the elastic response to the same load increment.
   */
  constexpr double mechanism_stiffness_ratio = 0.1;

  /**
   * The knee of the load-displacement curve: the last accepted state
   * before the first accepted step whose secant stiffness fell below this
   * fraction of the elastic one (displacements a hundred times the elastic
   * response to its load increment). It is reported beside the collapse
   * load as a serviceability figure, not as the collapse: where a curve
   * rounds off slowly the load goes on rising past it (a rough rigid
   * circular footing: about 1% more), and on a curve that levels off like
   * a hyperbola the knee lies at 90% of the limit.
   */
  constexpr double mechanism_knee_ratio = 0.01;

  /// An accepted state of the load-displacement curve.
  struct CurvePoint
  {
    double displacement;
    double load;
  };

  /**
   * The load's rise while the displacement doubled, up to the state
   * (@p displacement, @p load): L / L_h - 1, with L_h the load of the
   * latest of the accepted @p states whose displacement is at most half
   * this one (of the same sign, its load non-zero and of the same sign);
   * NaN where there is none. On a curve that levels off like a hyperbola,
   * L = L_lim d / (d + d_0), the rise from d / 2 to d is
   * d_0 / (d + d_0), exactly the fraction of the limit still to come at
   * d: so a rise of at most the collapse resolution r says the load has
   * reached its plateau to r, whichever way the body is driven (and L_h,
   * taken at or below d / 2 on a rising curve, only overstates the rise).
   * A load that fell gives a rise below zero: one falling towards its
   * limit from an initial state above it (an active earth pressure from
   * the at-rest one) levels off to r when its magnitude is at most r.
   */
  double
  plateau_rise(const std::vector<CurvePoint> &states,
               const double                   displacement,
               const double                   load,
               const double                   offset = 0);

  /// @p displacement moved away from 0 by @p offset (>= 0): what the rules
  /// on a phase's curve measure (Phase::displacement_offset).
  double
  offset_displacement(const double displacement, const double offset);

  /// The latest of @p states whose displacement is at most half
  /// @p displacement and of its sign (nullptr: none): where
  /// plateau_rise() measures from. Both measure every displacement moved
  /// away from 0 by @p offset (offset_displacement()).
  const CurvePoint *
  state_at_half(const std::vector<CurvePoint> &states,
                const double                   displacement,
                const double                   offset = 0);


  /**
   * Or, for a step stopped by its iteration limit, the change of its
   * displacement still growing linearly: at the end at least this many
   * times the change at half the limit (2 for linear growth; a step
   * converging at rate rho gives 1 + rho^(N/2)).
   */
  constexpr double mechanism_growth_ratio = 1.8;

  /**
   * Under prescribed displacement, a programme whose load never rose by
   * at most the collapse resolution over a doubling of the displacement
   * (plateau_rise()) still reports its last load as levelled off when the
   * last step's load change per load factor is below this fraction of the
   * first step's and the load rose by at most plateau_fallback_rise over
   * the last doubling of the displacement, and says which rule it was.
   */
  constexpr double plateau_stiffness_ratio = 0.01;

  /**
   * The largest rise over the last doubling of the displacement
   * (plateau_rise()) with which a run that levelled off by the stiffness
   * rule still claims a plateau. A small stiffness alone is no plateau: a
   * rigid pile translated through sand keeps 0.7% of its elastic
   * stiffness at a tenth of its diameter, and its load still rises by 18%
   * over a doubling of the movement. On a curve levelling off like a
   * hyperbola the rise is the fraction of the limit still to come, so the
   * claim stays within this of the limit (a rigid circular footing on the
   * coarse mesh of tests/verification/circular_footing rises 1.1% over
   * its programme's last doubling, levelling off).
   */
  constexpr double plateau_fallback_rise = 0.02;


  /// What the load programme leaves behind.
  struct ProgrammeResult
  {
    bool         converged           = true;
    bool         any_step_converged  = false;
    double       last_converged_load = 0;
    double       first_failed_load   = std::numeric_limits<double>::quiet_NaN();
    unsigned int total_iterations    = 0;
    unsigned int converged_iterations = 0;
    unsigned int steps_run            = 0;
    unsigned int attempts             = 0;
    unsigned int steps_with_drift     = 0;
    DisplacementMeasure displacement{0, 0, 0};
    DisplacementMeasure converged_displacement{0, 0, 0};
    /// The load per load factor of the first and of the last converged
    /// step, for the plateau under prescribed displacement.
    double first_stiffness = std::numeric_limits<double>::quiet_NaN();
    double last_stiffness  = std::numeric_limits<double>::quiet_NaN();
    double last_converged_load_factor = 0;
    /// What the phase's load factors count from: 0, or 1 for a strength
    /// reduction, whose factor is F = 1 + load factor. The reason states
    /// F, as the history's load column does.
    double load_factor_origin = 0;
    /// The accepted states, in order.
    std::vector<CurvePoint> curve;
    /// Phase::displacement_offset: what the rules on the curve add to its
    /// displacements.
    double displacement_offset = 0;

    /// The knee (mechanism_knee_ratio): the last accepted load before
    /// the curve's secant stiffness fell below it (NaN: it never did);
    /// and whether it has been passed.
    double knee_load   = std::numeric_limits<double>::quiet_NaN();
    bool   knee_passed = false;
    /// The first accepted state on the plateau (plateau_rise() at most
    /// the collapse resolution; NaN: none): its load, load factor and
    /// displacement, its rise, and the displacement that rise is from.
    double plateau_load              = std::numeric_limits<double>::quiet_NaN();
    double plateau_load_factor       = std::numeric_limits<double>::quiet_NaN();
    double plateau_displacement      = std::numeric_limits<double>::quiet_NaN();
    double plateau_rise              = std::numeric_limits<double>::quiet_NaN();
    double plateau_from_displacement = std::numeric_limits<double>::quiet_NaN();

    /// How a run that a failed step ended, ended.
    bool stopped = false;
    /// Automatic stepping narrowed the failed step to its resolution: the
    /// bracket of a collapse load (also of one at 0).
    bool bracket_resolved = false;
    /// The step that ended it converged, on the mechanism (a probe that
    /// converged far down the curve, at a secant stiffness below
    /// mechanism_knee_ratio).
    bool stopped_on_mechanism = false;
    /// Under load: the step that ended it converged on the plateau
    /// (plateau_load), at the collapse resolution.
    bool stopped_on_plateau = false;
    /// The steps prescribed the work of the loads (Loading/Control =
    /// work): a failed one asked for no load factor, so it brackets
    /// nothing.
    bool by_work = false;
    /// The step that ended it converged to a state moving against its load
    /// (negative secant stiffness): no state the body can reach, since
    /// under a load increment an elastic-plastic body does positive work
    /// (Drucker), and no mechanism either.
    bool   against_load       = false;
    bool   non_finite         = false;
    double failed_load_factor = std::numeric_limits<double>::quiet_NaN();
    double stiffness_ratio    = std::numeric_limits<double>::quiet_NaN();
    double growth_ratio       = std::numeric_limits<double>::quiet_NaN();
    /// Where a probe beyond the failed step showed the mechanism.
    double probe_load_factor = std::numeric_limits<double>::quiet_NaN();
    /// The signal that interrupted the run (0: none), and the load
    /// factor of the step it stopped.
    int    interrupted_by          = 0;
    double interrupted_load_factor = std::numeric_limits<double>::quiet_NaN();
  };


  /// Whether a failed attempt shows a mechanism.
  bool
  shows_mechanism(const double stiffness_ratio, const double growth_ratio);

  /**
   * How the run @p run ended (RunSummary::outcome), the reason, and the
   * collapse load where there is one; @p under_load: whether the scene
   * applies tractions or pressures (AnalysisView::has_external_load()), else
   * it is driven by prescribed displacements, where a failed step is no
   * collapse and the load may reach a plateau. There a run with accepted
   * steps that drifted outside the yield surface (ProgrammeResult::
   * steps_with_drift) claims no plateau: its load is read off states that
   * are not the elastic-plastic response. Under load the collapse load is
   * the applied load of the last converged step, which the drift does not
   * change; the drift is reported beside it.
   */
  void
  judge_outcome(const bool             under_load,
                const ProgrammeResult &run,
                RunSummary            &summary);
} // namespace thinlayer

#endif
