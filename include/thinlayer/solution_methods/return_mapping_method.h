#ifndef thinlayer_solution_methods_return_mapping_method_h
#define thinlayer_solution_methods_return_mapping_method_h

#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/iteration_access.h>
#include <thinlayer/solution_methods/convergence_watch.h>
#include <thinlayer/solution_methods/growth_monitor.h>
#include <thinlayer/solution_methods/solution_method.h>

#include <vector>

namespace thinlayer
{
  /**
   * The norms of the out-of-balance force that the return-mapping methods
   * test for convergence (ReturnMappingMethod::evaluate_residual()).
   */
  struct ResidualNorms
  {
    unsigned int n_yielding;
    /// max |r| and |r|_2 over the free DoFs of all modes.
    double max;
    double l2;
    /// max |b| of the stress excess, and max |f| of the internal and
    /// external forces: the scales max |r| is measured against.
    double body_loads;
    double forces;
    /// max |f| of the internal forces of the accepted state, where the
    /// step starts (AnalysisView::accepted_force_scale()): the scale of
    /// round-off in a step that unloads the body to nothing (where every
    /// force of the target state vanishes).
    double start_forces;
  };


  /**
   * What the return-mapping methods (initial stress, accelerated initial
   * stress, Newton) share: they iterate on the out-of-balance force
   * r = lambda f - int B^T sigma, every point's stress coming from the
   * return mapping of its elastic trial stress sigma_0 + D (strain of the
   * step) (evaluate_residual()). This class runs the attempts at
   * a load step, cutting it back where the method allows, and tests
   * convergence; a derived class supplies one iteration, the correction of
   * the step's displacement increment.
   *
   * Convergence: the out-of-balance force against the stress excess (the
   * paper's body-load test: for the initial-stress method r is exactly the
   * change of those body loads between iterations) or against the largest
   * force, or the last change of the step's displacements against their
   * size; and, whatever the criterion, once the residual is at rounding
   * level (elastic steps).
   */
  template <int dim>
  class ReturnMappingMethod : public SolutionMethod<dim>
  {
  public:
    ReturnMappingMethod(const SolverParameters &parameters,
                        IterationAccess<dim>   &analysis);

    /// Allocates the work vectors; a derived class that overrides this
    /// calls it first.
    void
    initialize() override;

    /**
     * Attempts at the step in the parts SubStepping gives: a converged
     * attempt short of the target (after a cut-back) is accepted in the
     * body and the rest of the step tried again; a failed one is halved up
     * to max_cut_backs() times.
     */
    StepResult
    solve_step(const double new_load_factor) override;

    /// Keeps the accepted step's increment for the next step's predictor;
    /// a derived class that overrides this calls it.
    void
    state_accepted() override;

    /// Under work control each attempt starts from the secant predictor
    /// scaled to the step's work, and a derived class that supports it
    /// corrects load_factor_now with the displacements.
    void
    set_work_control(const bool on) override;

  protected:
    /**
     * One iteration towards the load factor @p target: from the modes'
     * residuals (and @p norms, their norms), set each mode's correction,
     * call remember_increments() before changing the step increments, and
     * leave the new increments with their residual norms in @p norms.
     * Counts into @p result. False if the iteration cannot go on (a
     * singular tangent): the attempt has then failed.
     */
    virtual bool
    iterate(const double target, ResidualNorms &norms, StepResult &result) = 0;

    /// Iterations per attempt (Solver/Maximum iterations).
    virtual unsigned int
    max_iterations() const;

    /// How often a failed attempt may be halved (none).
    virtual unsigned int
    max_cut_backs() const;

    /// At the start of every attempt.
    virtual void
    start_attempt();

    /// The residual of the attempt's starting increment (the predictor).
    virtual ResidualNorms
    starting_residual(const double target);

    /**
     * Whether to end the attempt, as failed, before its iteration limit,
     * from the residuals so far (@p watch): never, unless a method knows
     * better.
     */
    virtual bool
    gives_up(const ConvergenceWatch &watch) const;


    /**
     * Stresses at every point and station by return mapping of the trial
     * stresses of the step increments (with @p tangents, keeping the
     * consistent tangents there); then each mode's residual (condensed
     * onto the free DoFs) at load factor @p target, and its norms.
     */
    ResidualNorms
    evaluate_residual(const double target, const bool tangents = false);

    /// Each mode's correction K_m^-1 r_m with its elastic factor.
    void
    elastic_corrections();

    /// Keep each mode's step increment, for the displacement criterion.
    void
    remember_increments();

    /// The work of the unit loads on @p displacements, sum over the modes
    /// of f_m^T u_m: what work control prescribes of a step's increment.
    double
    work_of(const ModeVectors &displacements) const;

    /// Loading/Control = work (set_work_control()).
    bool work_control = false;
    /// Under work control: the work f^T du the attempt's increment is to
    /// have.
    double step_work = 0;
    /// The load factor the attempt's residual is evaluated at: the target
    /// under load control; under work control an unknown that the
    /// iterations correct.
    double load_factor_now = 0;

    const SolverParameters &parameters;
    IterationAccess<dim>   &analysis;
    /// Per mode: the correction of the step increment, and the step
    /// increment before it.
    ModeVectors correction;
    ModeVectors previous_increment;
    /// Per mode: the out-of-balance force of the last residual evaluation,
    /// condensed onto the free DoFs.
    ModeVectors residual;

  private:
    GrowthMonitor    growth;
    ConvergenceWatch watch;

    /**
     * The secant predictor: each mode's increment of the last accepted
     * step and that step's size in load factor (0: none yet). An attempt
     * in the same direction starts from that increment scaled to its own
     * size rather than from the elastic response to the step's prescribed
     * displacements (predict()), so that a step along a plastic branch
     * starts near its end. The scaled increment meets the step's
     * prescribed displacements exactly: they are proportional to the load
     * factor.
     */
    ModeVectors accepted_increment;
    double      accepted_step        = 0;
    double      accepted_load_factor = 0;
    /// The work of the loads on accepted_increment.
    double accepted_step_work = 0;
    /// Per mode: the nodal forces of the stress excess (trial less
    /// returned stresses); and a work vector.
    ModeVectors stress_excess;
    ModeVector  condensed;

    /**
     * The increment an attempt to @p target starts from: the secant
     * predictor, or, for the first step and a reversal of the load, the
     * body's elastic response to the step's prescribed displacements
     * alone (its loads enter with the first correction).
     */
    void
    predict(const double target);

    /**
     * Under work control: the secant predictor scaled to the step's work,
     * from the accepted load factor (near the limit a load factor scaled
     * with the work would start beyond it; the first correction finds
     * it); none where no step has been accepted yet.
     */
    void
    predict_by_work();

    /// Iterations from the accepted state to @p target; true if converged.
    bool
    attempt(const double target, StepResult &result);

    bool
    converged(const ResidualNorms &norms);
  };
} // namespace thinlayer

#endif
