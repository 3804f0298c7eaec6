#ifndef thinlayer_stepping_step_solver_h
#define thinlayer_stepping_step_solver_h

#include <thinlayer/analysis/step_access.h>
#include <thinlayer/parameters/run_sections.h>
#include <thinlayer/solution_methods/solution_method.h>
#include <thinlayer/solution_methods/step_result.h>

#include <memory>

namespace thinlayer
{
  /**
   * The stepping's hold on the solution method: it owns the method that
   * the Solver section names, hands it the analysis, and runs one load
   * step at a time: the method's attempt, the end of the attempt in the
   * analysis (its state checked: a state that is not finite has not
   * converged), and the acceptance or rejection of that state in both.
   * The analysis never calls the method; this is the one place where the
   * two meet.
   */
  template <int dim>
  class StepSolver
  {
  public:
    /// The method of @p parameters on @p analysis, which must be set up.
    StepSolver(const SolverParameters &parameters, StepAccess<dim> &analysis);

    ~StepSolver();

    /**
     * An attempt at a load step from the accepted state to the total load
     * factor @p load_factor. Its state (converged or not: a failed step
     * shows the mechanism) is the analysis's current one, and stays
     * pending until accept() or reject(). A step whose displacements,
     * stresses or forces are not finite has not converged
     * (StepResult::non_finite). Nor has one that a method returning its
     * stresses to the yield surface left more than 10 TOL outside it
     * (StepResult::outside_surface): its return lost to round-off what
     * it returned, as it does at displacements some 1e16 times the
     * strains the strength allows (a layer of aspect ratio 1e6 sliding
     * on), where a step "converges" in one iteration with stresses
     * several times the strength and a load past the collapse.
     * @p final: a failure would end the run
     * (SolutionMethod::set_final_attempt()).
     */
    StepResult
    solve(const double load_factor, const bool final = true);

    /**
     * From now on (@p on) or no longer, solve() is given the work of the
     * loads on the step (f^T du) rather than its load factor, and the
     * load factor is found with the displacements (StepResult::
     * load_factor; Loading/Control = work).
     */
    void
    set_work_control(const bool on);

    /// A new phase has begun (StepAccess::begin_phase()): the method starts
    /// afresh, keeping nothing of the last phase's steps (its predictor).
    void
    begin_phase();

    /// Make the pending state the accepted one.
    void
    accept();

    /// Return to the accepted state.
    void
    reject();

  private:
    StepAccess<dim>                     &analysis;
    std::unique_ptr<SolutionMethod<dim>> method;
    /// Solver/Tolerance: TOL.
    double tolerance;
    /// set_work_control().
    bool work_control = false;
  };
} // namespace thinlayer

#endif
