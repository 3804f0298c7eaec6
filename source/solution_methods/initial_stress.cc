#include <thinlayer/solution_methods/initial_stress.h>

namespace thinlayer
{
  template <int dim>
  bool
  InitialStressMethod<dim>::iterate(const double   target,
                                    ResidualNorms &norms,
                                    StepResult & /*result*/)
  {
    this->elastic_corrections();
    this->remember_increments();
    for (unsigned int m = 0; m < this->analysis.n_modes(); ++m)
      this->analysis.get_step_increment()[m] += this->correction[m];
    norms = this->evaluate_residual(target);
    return true;
  }


  template class InitialStressMethod<2>;
  template class InitialStressMethod<3>;
} // namespace thinlayer
