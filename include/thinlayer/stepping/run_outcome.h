#ifndef thinlayer_stepping_run_outcome_h
#define thinlayer_stepping_run_outcome_h

#include <thinlayer/output/run_summary.h>
#include <thinlayer/postprocess/displacement_measure.h>

#include <limits>

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
   * A step that converges under load with a secant stiffness below this
   * fraction of the elastic one (displacements a hundred times the
   * elastic response) has reached the mechanism as well: automatic
   * stepping brackets this knee of the load-displacement curve rather
   * than accepting states along it. Beyond the knee, a thin layer's
   * curve can creep on for several per cent of load at a hundredth of
   * the elastic stiffness and less (Case 2 at aspect ratio 1000: from
   * 1.03 to 1.10, with displacements 3.7 to 213 times the footing's
   * elastic 1.6), and how far a method follows that creep depends on its
   * iteration budget, not on the body; the knee does not (Prandtl's
   * curve stays above 0.02 of the elastic stiffness to within 0.3% of
   * (2 + pi)c, so there the knee is the limit load).
   */
  constexpr double mechanism_knee_ratio = 0.01;

  /**
   * Or, for a step stopped by its iteration limit, the change of its
   * displacement still growing linearly: at the end at least this many
   * times the change at half the limit (2 for linear growth; a step
   * converging at rate rho gives 1 + rho^(N/2)).
   */
  constexpr double mechanism_growth_ratio = 1.8;

  /**
   * Under prescribed displacement the load has reached its plateau when
   * the last step's load change per load factor is below this fraction
   * of the first step's.
   */
  constexpr double plateau_stiffness_ratio = 0.01;


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

    /// How a run that a failed step ended, ended.
    bool stopped = false;
    /// Automatic stepping narrowed the failed step to its resolution: the
    /// bracket of a collapse load (also of one at 0).
    bool bracket_resolved = false;
    /// The step that ended it converged, on the mechanism.
    bool stopped_on_mechanism = false;
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
   * applies tractions or pressures (Analysis::has_external_load()), else
   * it is driven by prescribed displacements, where a failed step is no
   * collapse and the load may reach a plateau.
   */
  void
  judge_outcome(const bool             under_load,
                const ProgrammeResult &run,
                RunSummary            &summary);
} // namespace thinlayer

#endif
