#ifndef thinlayer_solvers_singular_matrix_h
#define thinlayer_solvers_singular_matrix_h

#include <stdexcept>

namespace thinlayer
{
  /**
   * The matrix given to a factorisation is singular (a zero pivot, not
   * positive definite): a mechanism or missing supports, which the caller
   * explains in terms of the model or takes as the answer (Newton's
   * tangent at collapse). Any other failure of a factorisation (memory, a
   * solver option its build lacks) is a LinearSolverFailure, which no
   * caller may mistake for a property of the model.
   */
  class SingularMatrix : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace thinlayer

#endif
