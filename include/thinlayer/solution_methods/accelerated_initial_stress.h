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
                                   Analysis<dim>          &analysis);

    void
    initialize() override;

  protected:
    bool
    iterate(const double   target,
            ResidualNorms &norms,
            StepResult    &result) override;

    /// Forgets the acceleration history: each attempt starts afresh.
    void
    start_attempt() override;

  private:
    AndersonAcceleration<ModeVector> anderson;
    /// The step increments of all modes and their corrections, each rank's
    /// own DoFs of every mode in turn (on one rank mode m's DoF i at
    /// m * n_dofs + i): the vectors Anderson acceleration works on.
    ModeVector stacked_increment;
    ModeVector stacked_correction;
  };
} // namespace thinlayer

#endif
