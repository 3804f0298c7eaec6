#ifndef thinlayer_solvers_factorised_stiffness_h
#define thinlayer_solvers_factorised_stiffness_h

#include <deal.II/base/array_view.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The constant stiffness matrix, factorised once and then used for every
   * forward/backward substitution of the constant-stiffness iterations,
   * which is where most of their time goes.
   *
   * Two direct solvers of SuiteSparse: CHOLMOD's supernodal Cholesky, for
   * the condensed stiffness is symmetric positive definite (half the work
   * of an LU factor, and no iterative refinement on every solve), or
   * UMFPACK's LU through deal.II.
   */
  class FactorisedStiffness
  {
  public:
    enum class Method
    {
      cholmod,
      umfpack
    };

    explicit FactorisedStiffness(const Method method = Method::cholmod);

    ~FactorisedStiffness();

    /**
     * Factorise @p matrix. Throws SingularMatrix if it is singular (or,
     * for CHOLMOD, not positive definite), std::runtime_error if CHOLMOD
     * fails otherwise (out of memory). CHOLMOD keeps the symbolic
     * analysis (ordering, elimination tree) of the last matrix and reuses it
     * when the next one has the same SparsityPattern object, whose pattern
     * must then not have changed.
     */
    void
    factorize(const SparseMatrix<double> &matrix);

    /// Replace @p rhs by the solution of K x = rhs.
    void
    solve(const ArrayView<double> &rhs);

  private:
    const Method method;
    /// CHOLMOD's state, behind a pointer to keep its header out of ours.
    struct Cholmod;
    std::unique_ptr<Cholmod> cholmod;
    SparseDirectUMFPACK      umfpack;
  };
} // namespace thinlayer

#endif
