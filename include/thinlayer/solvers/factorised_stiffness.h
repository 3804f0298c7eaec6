#ifndef thinlayer_solvers_factorised_stiffness_h
#define thinlayer_solvers_factorised_stiffness_h

#include <deal.II/base/array_view.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/solvers/factor_cost.h>

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
   * UMFPACK's LU for an unsymmetric matrix (Newton's tangent with
   * non-associated flow).
   *
   * Both are called directly rather than through deal.II, for the size of
   * their pivots. A matrix that is singular in exact arithmetic (a
   * mechanism, interface elements too soft for the cells beside them)
   * factorises with round-off for its zero pivots, whose sign and size
   * depend on the BLAS kernels of the processor: judged by their sign
   * alone (CHOLMOD's "not positive definite", UMFPACK's exact zero), the
   * same scene was refused on a processor with AVX2 kernels and solved into
   * noise, without a word, on one with AVX-512 kernels. A factor whose
   * smallest pivot is below a set fraction of its largest is therefore
   * singular, whatever its sign, as MUMPS's null-pivot detection does on
   * several ranks.
   */
  class FactorisedStiffness
  {
  public:
    enum class Method
    {
      cholmod,
      umfpack
    };

    /**
     * A factorisation by @p method that takes a matrix whose pivot ratio
     * is below @p minimum_pivot_ratio as singular. Zero keeps the solvers'
     * own verdicts alone (a pivot that is not positive, or exactly zero):
     * Newton's tangent, whose pivots fall continuously towards zero as the
     * load approaches collapse, is singular only where its factor fails.
     */
    explicit FactorisedStiffness(const Method method = Method::cholmod,
                                 const double minimum_pivot_ratio = 0);

    ~FactorisedStiffness();

    /**
     * The smallest pivot ratio of an elastic stiffness matrix (CHOLMOD: the
     * diagonal of D in L D L^T; UMFPACK: of U; the smallest over the
     * largest). Below it the solution keeps fewer than about four digits
     * (its error grows as the machine epsilon over the ratio), and the
     * matrix is taken as singular. The zero pivots of singular matrices
     * came out at 2e-18 of the largest, zero or negative; the elastic matrices
     * of the tests and of the paper's scenes are above 4e-7, and a layer 1000
     * times stiffer than the soil beside it at aspect ratio 10^5 gives
     * 7.5e-9 (the ratio falls as 1 / (aspect ratio x modulus ratio)).
     */
    static constexpr double elastic_pivot_ratio = 1e-12;

    /**
     * Factorise @p matrix. Throws SingularMatrix if its pivot ratio is
     * below the minimum, or if CHOLMOD finds it not positive definite or
     * UMFPACK a zero pivot; LinearSolverFailure if the solver fails otherwise
     * (out of memory). CHOLMOD keeps the symbolic analysis (ordering,
     * elimination tree) of the last matrix and reuses it when the next one has
     * the same SparsityPattern object, whose pattern must then not have
     * changed.
     */
    void
    factorize(const SparseMatrix<double> &matrix);

    /// Replace @p rhs by the solution of K x = rhs.
    void
    solve(const ArrayView<double> &rhs);

    /// The operations of the last successful factorisation and of a
    /// substitution with it; none before one.
    FactorCost
    cost() const;

  private:
    /// factorize() for Method::umfpack.
    void
    factorize_umfpack(const SparseMatrix<double> &matrix);

    const Method method;
    const double minimum_pivot_ratio;
    /// The solvers' states, behind pointers to keep their headers out of
    /// ours.
    struct Cholmod;
    struct Umfpack;
    std::unique_ptr<Cholmod> cholmod;
    std::unique_ptr<Umfpack> umfpack;
    FactorCost               last_cost;
  };
} // namespace thinlayer

#endif
