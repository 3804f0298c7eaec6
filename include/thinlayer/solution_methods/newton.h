#ifndef thinlayer_solution_methods_newton_h
#define thinlayer_solution_methods_newton_h

#include <thinlayer/analysis/coupled_system.h>
#include <thinlayer/solution_methods/return_mapping_method.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  /**
   * Newton's method: the correction K_t^-1 r with the consistent tangent
   * K_t of the return mappings, assembled and refactorised every
   * iteration, a backtracking line search on |r|_2, and, with the load
   * programme as given, the load step halved (Solver/Maximum cut-backs)
   * when an attempt does not converge in Solver/Maximum Newton iterations
   * (automatic stepping halves failed steps itself). An attempt starts
   * from the secant predictor (ReturnMappingMethod), its first correction
   * with the tangents at that predicted state.
   *
   * In the Fourier case the stations mix the harmonics, so the consistent
   * tangent couples them: it is one matrix over all modes, mode m's DoFs
   * shifted by m * n_dofs, each block condensed with its mode's
   * constraints (in plane strain, the one mode's matrix): a CoupledSystem,
   * to which every element group of the analysis adds its part
   * (ElementGroup::add_coupled_tangent()).
   */
  template <int dim>
  class NewtonMethod : public ReturnMappingMethod<dim>
  {
  public:
    using ReturnMappingMethod<dim>::ReturnMappingMethod;

    /// The coupled system and its sparsity.
    void
    initialize() override;

  protected:
    bool
    iterate(const double   target,
            ResidualNorms &norms,
            StepResult    &result) override;

    unsigned int
    max_iterations() const override;

    unsigned int
    max_cut_backs() const override;

    /// With the tangents at the predicted state, so that the first
    /// correction is Newton's (the accepted state's tangents made it
    /// overshoot: on Prandtl's footing most first iterations needed the
    /// line search).
    ResidualNorms
    starting_residual(const double target) override;

    /**
     * When the residual stagnates (ConvergenceWatch::stagnating()): six
     * iterations that did not halve the best residual before them. While
     * a thin layer's set of yielding points settles, Newton's residual
     * wanders for a few iterations before it falls (four gave up a step
     * of Case 2 at aspect ratio 1000 that converges); an attempt given up
     * is only ever one the stepping halves anyway
     * (SolutionMethod::set_final_attempt()).
     */
    bool
    gives_up(const ConvergenceWatch &watch) const override;


  private:
    /// Assemble and factorise the tangent; false if it is singular.
    bool
    factorise_tangent();

    /// The tangent over all modes, and its factors.
    std::unique_ptr<CoupledSystem> system;
  };
} // namespace thinlayer

#endif
