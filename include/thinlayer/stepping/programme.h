#ifndef thinlayer_stepping_programme_h
#define thinlayer_stepping_programme_h

#include <deal.II/base/timer.h>

#include <thinlayer/analysis/step_access.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/load_stepping.h>
#include <thinlayer/stepping/run_outcome.h>
#include <thinlayer/stepping/step_solver.h>

#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace thinlayer
{
  template <int dim>
  class LayerProfile;
  class OutputWriter;
  template <int dim>
  class Monitors;

  /**
   * One phase of a run (Initial state, Loading): its name, as
   * history.csv's phase column and summary.json give it, its load
   * programme, and the number its first step takes (the steps of a run
   * are numbered on across its phases, as its fields files are).
   */
  struct Phase
  {
    std::string       name;
    LoadingParameters loading;
    unsigned int      steps_before = 0;
    /// A strength reduction phase: the load factor raises the factor F =
    /// 1 + load factor by which the strengths are divided
    /// (StepAccess::reduce_strength()), and F is the phase's load.
    bool strength_reduction = false;
    /**
     * What the rules on the phase's load-displacement curve (the plateau,
     * plateau_rise(); the doubling of the displacement) add to each of its
     * displacements. A strength reduction measures its displacements from
     * its start and raises no load: they start at round-off (1e-13), from
     * which any growth "doubles", and the plateau rule would fire at first
     * yield. It moves them away from 0 by a scale of its own, so that
     * growth is measured against that: the larger of the displacement the
     * body reached before it and the elastic displacement of the loads it
     * carries (offset_displacement()). Other phases raise a load, whose
     * displacements are their scale: 0.
     */
    double displacement_offset = 0;
  };


  /**
   * The load programme of a phase of a run, attempt by attempt: LoadStepping
   * says which load factor comes next, the StepSolver solves it with the
   * solution method, and the programme measures the attempt (load,
   * displacement, secant stiffness, the load's rise over the last doubling
   * of the displacement), decides whether a
   * converged state is to count as failed (moving against its load; or, in
   * a step longer than the collapse resolution, on the plateau of the load
   * or more than doubling the displacement: cut back, so that the curve
   * is sampled at least once every doubling and the plateau's start is
   * bracketed), ends the
   * run where a step at that resolution reaches the plateau, notes the
   * knee of the curve, probes beyond a failed step that shows no
   * mechanism, and writes
   * each attempt's row and fields as it ends, with one line on screen.
   * What the end of the programme means (collapse, plateau, not converged)
   * is judged from its ProgrammeResult by judge_outcome(), with the
   * thresholds named in run_outcome.h.
   */
  template <int dim>
  class Programme
  {
  public:
    Programme(const Parameters                     &p,
              const Phase                          &phase,
              StepAccess<dim>                      &analysis,
              StepSolver<dim>                      &solver,
              const Monitors<dim>                  &monitors,
              const std::vector<LayerProfile<dim>> &layers,
              OutputWriter                         &writer,
              TimerOutput                          &timer,
              std::ostream                         &out)
      : p(p)
      , phase(phase)
      , loading(phase.loading)
      , analysis(analysis)
      , solver(solver)
      , monitors(monitors)
      , layers(layers)
      , writer(writer)
      , timer(timer)
      , out(out)
    {}

    ProgrammeResult
    run();

  private:
    /// Converged steps that took at most this many iterations are easy:
    /// the next may be longer.
    unsigned int
    easy_iterations() const;

    /**
     * Loading/Control = work, after the programme's first step: each step
     * prescribes the work of the loads on it, f^T du, and its load factor
     * is found with its displacements (Sysala et al.'s indirect
     * continuation). As the work grows the load factor rises towards the
     * limit, where the displacements grow without it: the collapse is
     * reached as the plateau of the load (a step that lands there ends
     * the run), with no attempt beyond the limit to fail. The first
     * step's work is the scale; a step's work doubles after an easy step,
     * halves after one over half the iteration limit and after a failure,
     * and never exceeds the work done so far (the work at most doubles, so
     * the plateau rule has a state every doubling). A failure at the
     * resolution's fraction of the work done ends the run, unbracketed;
     * so does reaching the programme's end.
     */
    void
    run_by_work();

    /// The fields (and a Fourier body's revolved view) of the current
    /// state, as step @p step at @p load_factor.
    void
    write_fields(const unsigned int step,
                 const double       load_factor,
                 const bool         on_curve);

    /**
     * The fields of the last accepted state, if Output/Fields interval
     * skipped them: at the end of the phase. @p pending_failure: the
     * current state is a failed attempt's, rejected first.
     */
    void
    write_last_state(const bool pending_failure);

    struct Attempt
    {
      unsigned int step;
      double       load_factor;
      StepResult   result;
      double       load;
      /// AnalysisView::secant_stiffness_ratio() of the attempt's state.
      double stiffness_ratio;
      /// A converged attempt below the knee (mechanism_knee_ratio): the
      /// evidence of a mechanism where it is a probe beyond a failed step.
      bool on_mechanism;
      /// plateau_rise() of a converged attempt (NaN otherwise); whether it
      /// is at most the collapse resolution (the load has reached its
      /// plateau); and whether the attempt's displacement grew more than
      /// twice as much as its load from the last accepted state.
      double rise;
      bool   on_plateau;
      bool   doubled;
      /// A converged attempt moving against its load: counted as failed.
      bool against_load;
    };

    /// Whether the phase is driven as a load is (a collapse under it is
    /// bracketed): by a load, or by the strength reduction factor.
    bool
    under_load() const;

    /**
     * Whether automatic stepping has narrowed the bracket between the last
     * converged state and the attempt @p failed to the collapse
     * resolution, relative to the phase's load at its ends.
     */
    bool
    bracket_resolved(const Attempt &failed) const;

    /**
     * Whether the body's strength has no scale of its own: no cohesion,
     * adhesion, tensile strength or weight, from an unstressed start. Its
     * response to a load is then the same at every size of the load, and a
     * step that fails at a fraction of the first step fails at any.
     */
    bool
    strength_has_no_scale() const;

    /// Solve the step to @p load_factor and measure it; @p final: a
    /// failure would not be cut back (LoadStepping::failure_is_final()).
    Attempt
    attempt(const unsigned int step,
            const double       load_factor,
            const bool         final);

    /// Its row in history.csv, its fields unless it is to be retried,
    /// and its line on screen.
    void
    record(const Attempt           &a,
           const LoadStepping::Next next,
           const bool               probe = false);

    /// Take a converged attempt's figures and accept its state.
    void
    accept(const Attempt &a);

    /**
     * Automatic stepping ended at a failed step that shows no mechanism:
     * at the limit load itself a method converges slowly rather than
     * creeps. Try the same step once more beyond it, from the accepted
     * state; a mechanism there is the evidence. The probe is never
     * accepted.
     */
    void
    probe_beyond(const Attempt &failed);

    const Parameters                     &p;
    const Phase                          &phase;
    const LoadingParameters              &loading;
    StepAccess<dim>                      &analysis;
    StepSolver<dim>                      &solver;
    const Monitors<dim>                  &monitors;
    const std::vector<LayerProfile<dim>> &layers;
    OutputWriter                         &writer;
    TimerOutput                          &timer;
    std::ostream                         &out;
    ProgrammeResult                       result;

    /// The states of the curve recorded so far, for Output/Fields
    /// interval.
    unsigned int curve_states = 0;
    /// The work of the loads on the accepted steps, f^T u (where the
    /// method says it). Whether the steps are under work control is
    /// result.by_work.
    double accepted_work = 0;
    /// The step and load factor of the last accepted state, if its fields
    /// are not written.
    std::optional<std::pair<unsigned int, double>> unwritten_state;
  };
} // namespace thinlayer

#endif
