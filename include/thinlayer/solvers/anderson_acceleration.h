#ifndef thinlayer_solvers_anderson_acceleration_h
#define thinlayer_solvers_anderson_acceleration_h

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <deque>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Anderson acceleration (Anderson 1965; Walker and Ni 2011, "type II") of
   * a fixed-point iteration x <- x + g(x). For the initial-stress method g
   * is the correction K^-1 r(x) with the constant elastic stiffness K, so
   * the accelerated scheme still uses one factorisation; what it adds is a
   * small least-squares problem per iteration over the last few iterates:
   *   gamma = argmin |g_k - dG gamma|,
   *   x_k+1 = x_k + g_k - (dX + dG) gamma,
   * with dX, dG the differences of successive iterates and corrections.
   * Without history (the first iteration of a step) it is the plain
   * fixed-point step. On the modes of a mechanism, where plain constant
   * stiffness iterations creep with a rate near one, the least-squares
   * combination extrapolates along the creep, which is why it pays there.
   */
  template <typename VectorType = Vector<double>>
  class AndersonAcceleration
  {
  public:
    /// @p depth: how many previous iterates are combined, at least 1.
    explicit AndersonAcceleration(const unsigned int depth);

    /// Forget the history (at the start of a load step).
    void
    reset();

    /**
     * Given the iterate @p x and its correction @p g, replace @p x by the
     * next iterate.
     */
    void
    update(VectorType &x, const VectorType &g);

  private:
    const unsigned int     depth;
    VectorType             previous_x;
    VectorType             previous_g;
    bool                   has_previous;
    std::deque<VectorType> dX;
    std::deque<VectorType> dG;
    // Work space of the least-squares solve, kept so that an iteration
    // allocates nothing once the history is full.
    std::vector<VectorType>   Q;
    std::vector<unsigned int> kept;
    std::vector<double>       R;
    std::vector<double>       gamma;
  };
} // namespace thinlayer

#endif
