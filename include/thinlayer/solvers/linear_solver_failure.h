#ifndef thinlayer_solvers_linear_solver_failure_h
#define thinlayer_solvers_linear_solver_failure_h

#include <stdexcept>

namespace thinlayer
{
  /**
   * A linear solver could not do its work for a reason that is no property
   * of the model: too little memory for the factors, a solver option its
   * build lacks, conjugate gradients not converging in their iteration
   * limit. The run ends with the solver's own account of it, which says
   * what to change (another solver, more iterations, more ranks).
   */
  class LinearSolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace thinlayer

#endif
