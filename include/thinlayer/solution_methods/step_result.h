#ifndef thinlayer_solution_methods_step_result_h
#define thinlayer_solution_methods_step_result_h

#include <limits>

namespace thinlayer
{
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
    /// Newton: GMRES iterations of its corrections.
    unsigned int krylov_iterations = 0;
    /// Whether the displacements (or stresses) of the step are not finite
    /// numbers: never converged.
    bool non_finite = false;
    /// Whether the method's iterations met their test with stresses more
    /// than 10 TOL outside the yield surface, which a method returning
    /// them to it leaves only where round-off has taken over: never
    /// converged (StepSolver::solve()).
    bool outside_surface = false;
    /// A step that ran to its iteration limit: the change of its
    /// displacement at the end against that at half the limit
    /// (GrowthMonitor; near 2 while it creeps along a mechanism); NaN
    /// otherwise.
    double growth_ratio = std::numeric_limits<double>::quiet_NaN();
    /// The load factor of the step's state: the one asked for under load
    /// control, the one found under work control (StepSolver::solve()).
    double load_factor = std::numeric_limits<double>::quiet_NaN();
    /// The work of the loads on the step's displacement increment, f^T du
    /// (summed over the modes), where the method knows it; NaN otherwise.
    double work = std::numeric_limits<double>::quiet_NaN();
  };
} // namespace thinlayer

#endif
