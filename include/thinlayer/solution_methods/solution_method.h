#ifndef thinlayer_solution_methods_solution_method_h
#define thinlayer_solution_methods_solution_method_h

#include <thinlayer/parameters/parameters.h>

#include <limits>
#include <memory>

namespace thinlayer
{
  template <int dim>
  class Analysis;

  /**
   * What one load step reports (history.csv has one row per step).
   */
  struct StepResult
  {
    unsigned int iterations;
    bool         converged;
    /// Max over points (and stations) of F / strength after the step: NaN
    /// where no material can yield.
    double max_yield_ratio;
    /// Points (and stations) with F > 0 at the end of the step.
    unsigned int plastic_points;
    /// Newton: how often the step was halved.
    unsigned int cut_backs = 0;
    /// Newton: tangent factorisations.
    unsigned int factorisations = 0;
    /// Whether the displacements (or stresses) of the step are not finite
    /// numbers: never converged.
    bool non_finite = false;
    /// A step that ran to its iteration limit: the change of its
    /// displacement at the end against that at half the limit
    /// (GrowthMonitor; near 2 while it creeps along a mechanism); NaN
    /// otherwise.
    double growth_ratio = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * A way of solving the elasto-plastic equations of one load step on the
   * body of an Analysis: the paper's viscoplastic iterations, initial
   * stress (plain or Anderson-accelerated) or Newton. Each method is a
   * class of its own in source/solution_methods/, owns the state it needs
   * (work vectors, acceleration history, tangent system), and works
   * through the body's modes, point loop and residual evaluation.
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

    /// Allocate the method's state; called once, after the body is set
    /// up.
    virtual void
    initialize() = 0;

    /**
     * Iterate from the body's accepted state (at Analysis::load_factor())
     * to the load factor @p new_load_factor. The step's state, converged
     * or not, is left in the body's modes and point history for the body
     * to accept. StepResult::max_yield_ratio is filled in by the body.
     */
    virtual StepResult
    solve_step(const double new_load_factor) = 0;

    /// The body has accepted the current state (a step, or a converged
    /// part of one): what the method keeps of a state is now that of the
    /// accepted one.
    virtual void
    state_accepted();

    /// The body has dropped the current state for the accepted one: the
    /// method returns to what it kept of that.
    virtual void
    state_rejected();
  };

  /**
   * The method that @p parameters name, working on @p analysis: the one
   * place that chooses by SolverParameters::Method.
   */
  template <int dim>
  std::unique_ptr<SolutionMethod<dim>>
  create_solution_method(const SolverParameters &parameters,
                         Analysis<dim>          &analysis);
} // namespace thinlayer

#endif
