#ifndef thinlayer_solution_methods_accelerated_initial_stress_h
#define thinlayer_solution_methods_accelerated_initial_stress_h

#include <deal.II/lac/vector.h>

#include <thinlayer/solution_methods/return_mapping_method.h>
#include <thinlayer/solvers/anderson_acceleration.h>

namespace thinlayer
{
  /**
   * The initial-stress method with Anderson acceleration
   * (AndersonAcceleration, Solver/Anderson depth previous iterates) of the
   * step increments of all modes at once: still one elastic factorisation,
   * plus a small least-squares problem per iteration, which extrapolates
   * along the slow creep of plain constant-stiffness iterations near
   * collapse.
   */
  template <int dim>
  class AcceleratedInitialStressMethod : public ReturnMappingMethod<dim>
  {
  public:
    AcceleratedInitialStressMethod(const SolverParameters &parameters,
                                   IterationAccess<dim>   &analysis);

    void
    initialize() override;

    /**
     * Give an attempt up as soon as its rate of convergence over the last
     * ten iterations says it will not converge within its iteration limit
     * (ConvergenceWatch::predicted_iterations()), rather than at the
     * limit: for a part of a method that has a costlier way to finish the
     * step (NewtonFallbackMethod). On its own the method runs every
     * attempt to its limit, where the growth of the displacement is the
     * evidence of a mechanism. @p give_up: whether to (the default of a
     * method on its own is not to).
     */
    void
    give_up_when_slow(const bool give_up);

  protected:
    bool
    iterate(const double   target,
            ResidualNorms &norms,
            StepResult    &result) override;

    /// Forgets the acceleration history: each attempt starts afresh.
    void
    start_attempt() override;

    bool
    gives_up(const ConvergenceWatch &watch) const override;

  private:
    AndersonAcceleration<ModeVector> anderson;
    /// The step increments of all modes and their corrections, each rank's
    /// own DoFs of every mode in turn (on one rank mode m's DoF i at
    /// m * n_dofs + i): the vectors Anderson acceleration works on.
    ModeVector stacked_increment;
    ModeVector stacked_correction;
    bool       slow_attempts_given_up = false;
  };
} // namespace thinlayer

#endif
