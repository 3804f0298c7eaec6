#ifndef thinlayer_solution_methods_solution_method_h
#define thinlayer_solution_methods_solution_method_h

#include <thinlayer/parameters/parameters.h>
#include <thinlayer/solution_methods/step_result.h>

#include <memory>

namespace thinlayer
{
  template <int dim>
  class IterationAccess;

  /**
   * A way of solving the elasto-plastic equations of one load step on the
   * body of an analysis, seen through IterationAccess: the paper's viscoplastic
   * iterations, initial stress (plain or Anderson-accelerated) or Newton. Each
   * method is a class of its own in source/solution_methods/, owns the state it
   * needs (work vectors, acceleration history, tangent system), and works on
   * the analysis it is given: it sets the step's displacement increments
   * and calls the analysis's point rules. The stepping owns the method
   * (StepSolver), ends each attempt in the analysis and tells the method
   * whether its state was accepted; the analysis never calls a method.
   *
   * To add a method: derive from this class in a new file pair under
   * solution_methods/, add its name to SolverParameters::Method and its
   * table, and one line to create_solution_method().
   */
  template <int dim>
  class SolutionMethod
  {
  public:
    virtual ~SolutionMethod() = default;

    /// Allocate the method's state, or start it afresh: called after the
    /// body is set up, and again at the start of each phase.
    virtual void
    initialize() = 0;

    /**
     * Iterate from the body's accepted state (at
     * AnalysisView::accepted_load_factor()) to the load factor
     * @p new_load_factor. The step's state, converged or not, is left in
     * the analysis (step increments and point states) for the stepping to
     * accept or reject. StepResult::max_yield_ratio and
     * StepResult::non_finite are the stepping's to fill in.
     */
    virtual StepResult
    solve_step(const double new_load_factor) = 0;

    /**
     * Whether the method can take steps under work control (Loading/
     * Control = work): Newton's, whose tangent gives the load factor's
     * correction with the displacements'.
     */
    virtual bool
    supports_work_control() const;

    /**
     * From now on (@p on) or no longer, each solve_step() is given the
     * work of the loads on the step, f^T du, rather than its load factor,
     * and finds the load factor with the displacements
     * (StepResult::load_factor).
     */
    virtual void
    set_work_control(const bool on);

    /// The body has accepted the current state (a step, or a converged
    /// part of one): what the method keeps of a state is now that of the
    /// accepted one.
    virtual void
    state_accepted();

    /// The body has dropped the current state for the accepted one: the
    /// method returns to what it kept of that.
    virtual void
    state_rejected();

    /**
     * Whether a failure of the next step would be final (the stepping
     * cuts it back no more): the failed state is then the evidence of
     * how the run ended (a mechanism, by its growth and secant
     * stiffness), so the method runs to its iteration limit. Otherwise a
     * method may give a hopeless attempt up early (ReturnMappingMethod::
     * gives_up()): the stepping halves it anyway.
     */
    virtual void
    set_final_attempt(const bool final);

    /**
     * Whether the method returns every point's stress to its yield
     * surface (a return mapping) before it tests convergence, so that a
     * converged state lies on or inside it to round-off (true); the
     * paper's viscoplastic iterations leave the excess that their last
     * increment did not relax, to TOL.
     */
    virtual bool
    returns_stresses_to_surface() const;

    /**
     * Tell @p composite, rather than this method, when the method accepts
     * a converged part of a step in the analysis: for a method that is part
     * of another (NewtonFallbackMethod), whose parts all keep state of the
     * accepted one.
     */
    void
    report_acceptance_to(SolutionMethod<dim> &composite);

  protected:
    /// The method to tell of a converged part of a step it accepted.
    SolutionMethod<dim> *acceptance_listener = this;
    /// set_final_attempt(): attempts run to their iteration limit.
    bool final_attempt = true;
  };

  /**
   * The method that @p parameters name, working on @p analysis: the one
   * place that chooses by SolverParameters::Method.
   */
  template <int dim>
  std::unique_ptr<SolutionMethod<dim>>
  create_solution_method(const SolverParameters &parameters,
                         IterationAccess<dim>   &analysis);
} // namespace thinlayer

#endif
