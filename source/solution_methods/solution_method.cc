#include <thinlayer/solution_methods/accelerated_initial_stress.h>
#include <thinlayer/solution_methods/initial_stress.h>
#include <thinlayer/solution_methods/newton.h>
#include <thinlayer/solution_methods/newton_fallback.h>
#include <thinlayer/solution_methods/solution_method.h>
#include <thinlayer/solution_methods/viscoplastic.h>

namespace thinlayer
{
  template <int dim>
  void
  SolutionMethod<dim>::state_accepted()
  {}


  template <int dim>
  void
  SolutionMethod<dim>::state_rejected()
  {}


  template <int dim>
  void
  SolutionMethod<dim>::set_final_attempt(const bool final)
  {
    final_attempt = final;
  }


  template <int dim>
  bool
  SolutionMethod<dim>::returns_stresses_to_surface() const
  {
    return true;
  }


  template <int dim>
  bool
  SolutionMethod<dim>::supports_work_control() const
  {
    return false;
  }


  template <int dim>
  void
  SolutionMethod<dim>::set_work_control(const bool on)
  {
    AssertThrow(!on || supports_work_control(),
                ExcMessage("This solution method cannot take steps under "
                           "work control."));
  }


  template <int dim>
  void
  SolutionMethod<dim>::report_acceptance_to(SolutionMethod<dim> &composite)
  {
    acceptance_listener = &composite;
  }


  template <int dim>
  std::unique_ptr<SolutionMethod<dim>>
  create_solution_method(const SolverParameters &parameters,
                         IterationAccess<dim>   &analysis)
  {
    using Method = SolverParameters::Method;
    switch (parameters.method)
      {
        case Method::viscoplastic:
          return std::make_unique<ViscoplasticMethod<dim>>(parameters,
                                                           analysis);
        case Method::initial_stress:
          return std::make_unique<InitialStressMethod<dim>>(parameters,
                                                            analysis);
        case Method::accelerated_initial_stress:
          return std::make_unique<AcceleratedInitialStressMethod<dim>>(
            parameters, analysis);
        case Method::newton:
          return std::make_unique<NewtonMethod<dim>>(parameters, analysis);
        case Method::accelerated_with_newton_fallback:
          return std::make_unique<NewtonFallbackMethod<dim>>(parameters,
                                                             analysis);
      }
    AssertThrow(false, ExcInternalError());
    return nullptr;
  }


  template class SolutionMethod<2>;
  template class SolutionMethod<3>;
  template std::unique_ptr<SolutionMethod<3>>
  create_solution_method(const SolverParameters &, IterationAccess<3> &);

  template std::unique_ptr<SolutionMethod<2>>
  create_solution_method(const SolverParameters &, IterationAccess<2> &);
} // namespace thinlayer
