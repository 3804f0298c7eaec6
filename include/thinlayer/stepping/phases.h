#ifndef thinlayer_stepping_phases_h
#define thinlayer_stepping_phases_h

#include <deal.II/base/timer.h>

#include <thinlayer/analysis/step_access.h>
#include <thinlayer/output/run_summary.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/run_outcome.h>
#include <thinlayer/stepping/step_solver.h>

#include <ostream>
#include <vector>

namespace thinlayer
{
  template <int dim>
  class LayerProfile;
  class OutputWriter;
  template <int dim>
  class Monitors;

  /**
   * The phases of a run, in order: the initial state (Initial state: the
   * K0 procedure's stresses, or gravity loading's programme), the loading
   * (the Loading section's programme of the Boundary sections' values),
   * further loadings (Phase 2, 3, ...: each its programme of its own
   * boundary values), and strength reduction (Strength reduction: a programme
   * of the factor by which strengths are divided). Each phase holds the loads
   * of the ones before it (StepAccess::begin_phase()); each programme is a
   * Programme, judged by judge_outcome(); a phase that does not complete
   * ends the run, and the summary's phase says which one its figures are
   * of.
   */
  template <int dim>
  class Phases
  {
  public:
    Phases(const Parameters                     &p,
           StepAccess<dim>                      &analysis,
           StepSolver<dim>                      &solver,
           const Monitors<dim>                  &monitors,
           const std::vector<LayerProfile<dim>> &layers,
           TimerOutput                          &timer,
           std::ostream                         &out);

    /**
     * What the phases need settled before anything is written: the K0
     * procedure's stresses (which throws InputError where the ground is
     * not level or a stress is outside its yield surface), and that the
     * loading applies something where it runs. Fills in the summary's
     * initial state.
     */
    void
    prepare(RunSummary &summary);

    /// Run the phases, writing through @p writer; the outcome of the last
    /// one run into @p summary. Returns that phase's result.
    ProgrammeResult
    run(OutputWriter &writer, RunSummary &summary);

  private:
    /// Whether the loading phase runs: after an initial state, only if
    /// the Boundary sections apply something.
    bool
    loading_runs() const;

    /// Judge the phase that ran as @p result (judge_outcome(), @p under_load
    /// as there) and list it, with its own outcome, in @p summary.phases.
    void
    judge(const ProgrammeResult &result,
          bool                   under_load,
          RunSummary            &summary) const;

    /// The displacement measure of the elastic response to the loads the
    /// accepted state carries: the scale of a strength reduction's growth
    /// (Phase::displacement_offset).
    double
    elastic_displacement_of_carried_loads();

    const Parameters                     &p;
    StepAccess<dim>                      &analysis;
    StepSolver<dim>                      &solver;
    const Monitors<dim>                  &monitors;
    const std::vector<LayerProfile<dim>> &layers;
    TimerOutput                          &timer;
    std::ostream                         &out;
  };
} // namespace thinlayer

#endif
