#include <thinlayer/solution_methods/accelerated_initial_stress.h>

namespace thinlayer
{
  template <int dim>
  AcceleratedInitialStressMethod<dim>::AcceleratedInitialStressMethod(
    const SolverParameters &parameters,
    Analysis<dim>          &analysis)
    : ReturnMappingMethod<dim>(parameters, analysis)
    , anderson(parameters.anderson_depth)
  {}


  template <int dim>
  void
  AcceleratedInitialStressMethod<dim>::initialize()
  {
    ReturnMappingMethod<dim>::initialize();
    const unsigned int n = this->analysis.get_dof_handler().n_dofs();
    stacked_increment.reinit(n * this->analysis.n_modes());
    stacked_correction.reinit(n * this->analysis.n_modes());
  }


  template <int dim>
  void
  AcceleratedInitialStressMethod<dim>::start_attempt()
  {
    anderson.reset();
  }


  template <int dim>
  bool
  AcceleratedInitialStressMethod<dim>::iterate(const double   target,
                                               ResidualNorms &norms,
                                               StepResult & /*result*/)
  {
    Analysis<dim>     &analysis = this->analysis;
    const unsigned int n        = analysis.get_dof_handler().n_dofs();
    this->elastic_corrections();
    this->remember_increments();
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      for (unsigned int i = 0; i < n; ++i)
        {
          stacked_increment[m * n + i]  = analysis.step_increment()[m][i];
          stacked_correction[m * n + i] = this->correction[m][i];
        }
    anderson.update(stacked_increment, stacked_correction);
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      for (unsigned int i = 0; i < n; ++i)
        analysis.step_increment()[m][i] = stacked_increment[m * n + i];
    norms = this->evaluate_residual(target);
    return true;
  }


  template class AcceleratedInitialStressMethod<2>;
} // namespace thinlayer
