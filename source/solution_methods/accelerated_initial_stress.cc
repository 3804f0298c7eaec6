#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solution_methods/accelerated_initial_stress.h>

namespace thinlayer
{
  template <int dim>
  AcceleratedInitialStressMethod<dim>::AcceleratedInitialStressMethod(
    const SolverParameters &parameters,
    IterationAccess<dim>   &analysis)
    : ReturnMappingMethod<dim>(parameters, analysis)
    , anderson(parameters.anderson_depth)
  {}


  template <int dim>
  void
  AcceleratedInitialStressMethod<dim>::initialize()
  {
    ReturnMappingMethod<dim>::initialize();
    // Each rank's rows of all modes, contiguous and in rank order.
    const ModeVectors  zero    = this->analysis.new_mode_vectors();
    const unsigned int n_modes = zero.size();
    const auto [first, last]   = zero[0].get_partitioner()->local_range();
    IndexSet owned(n_modes * zero[0].size());
    owned.add_range(n_modes * first, n_modes * last);
    for (ModeVector *v : {&stacked_increment, &stacked_correction})
      if (mpi::n_ranks() == 1)
        v->reinit(owned.size()); // no MPI without mpirun
      else
        v->reinit(owned, mpi::communicator());
  }


  template <int dim>
  void
  AcceleratedInitialStressMethod<dim>::give_up_when_slow(const bool give_up)
  {
    slow_attempts_given_up = give_up;
  }


  template <int dim>
  bool
  AcceleratedInitialStressMethod<dim>::gives_up(
    const ConvergenceWatch &watch) const
  {
    constexpr unsigned int window = 10;
    return slow_attempts_given_up && watch.iterations() >= window &&
           watch.predicted_iterations(this->parameters.tolerance, window) >
             this->max_iterations();
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
    IterationAccess<dim> &analysis = this->analysis;
    this->elastic_corrections();
    this->remember_increments();
    const unsigned int n =
      analysis.get_step_increment()[0].locally_owned_size();
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      for (unsigned int k = 0; k < n; ++k)
        {
          stacked_increment.local_element(m * n + k) =
            analysis.get_step_increment()[m].local_element(k);
          stacked_correction.local_element(m * n + k) =
            this->correction[m].local_element(k);
        }
    anderson.update(stacked_increment, stacked_correction);
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      for (unsigned int k = 0; k < n; ++k)
        analysis.get_step_increment()[m].local_element(k) =
          stacked_increment.local_element(m * n + k);
    norms = this->evaluate_residual(target);
    return true;
  }


  template class AcceleratedInitialStressMethod<2>;
  template class AcceleratedInitialStressMethod<3>;
} // namespace thinlayer
