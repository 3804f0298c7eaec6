#ifndef thinlayer_solution_methods_initial_stress_h
#define thinlayer_solution_methods_initial_stress_h

#include <thinlayer/solution_methods/return_mapping_method.h>

namespace thinlayer
{
  /**
   * The initial-stress method: constant (elastic) stiffness, every point
   * return-mapped, the step's displacement corrected by K^-1 r with the
   * elastic factor. The stress excess int B^T (trial - sigma) plays the
   * part of the paper's body loads; r is exactly their change between
   * iterations.
   */
  template <int dim>
  class InitialStressMethod : public ReturnMappingMethod<dim>
  {
  public:
    using ReturnMappingMethod<dim>::ReturnMappingMethod;

  protected:
    bool
    iterate(const double   target,
            ResidualNorms &norms,
            StepResult    &result) override;
  };
} // namespace thinlayer

#endif
