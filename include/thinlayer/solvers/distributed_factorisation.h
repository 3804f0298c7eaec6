#ifndef thinlayer_solvers_distributed_factorisation_h
#define thinlayer_solvers_distributed_factorisation_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/index_set.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/solvers/factor_cost.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * A stiffness matrix distributed over the MPI ranks by rows (each rank
   * its contiguous range of DoFs), factorised once by MUMPS through PETSc,
   * and then used for every forward/backward substitution: the direct
   * solver of runs on several ranks, whose factor is split over them as
   * the matrix is.
   *
   * The right-hand sides and solutions are whole vectors on every rank
   * (the state every rank holds): a solve takes each rank's rows of the
   * right-hand side and gives every rank the whole solution.
   */
  class DistributedFactorisation
  {
  public:
    /**
     * @p symmetric: the matrix is symmetric positive definite (the elastic
     * stiffness, an associated tangent), factorised as L D L^T; else LU.
     * @p block_low_rank_tolerance: with a positive value, MUMPS stores the
     * factor's large blocks as low-rank products to that fraction of the
     * matrix's norm (its ICNTL(35) = 2 and CNTL(7)), which makes a 3D
     * factorisation and its substitutions shorter and smaller.
     */
    explicit DistributedFactorisation(
      const bool   symmetric,
      const double block_low_rank_tolerance = 0);

    ~DistributedFactorisation();

    /**
     * Factorise @p matrix, whose rows are distributed as
     * @p owned_per_rank says. Throws SingularMatrix if MUMPS finds it
     * singular, and std::runtime_error naming MUMPS's error code if MUMPS
     * fails otherwise (on every rank: the answer is the same on all).
     * Factorising the same matrix object again after a success (new
     * values on the same pattern, as Newton's tangent) reuses MUMPS's
     * ordering and symbolic analysis. The factor keeps no reference to
     * @p matrix, which may be freed once factorised for good.
     */
    void
    factorize(const PETScWrappers::MPI::SparseMatrix &matrix,
              const std::vector<IndexSet>            &owned_per_rank);

    /// Replace this rank's @p rows of a right-hand side by its rows of
    /// the solution of K x = rhs (a collective call).
    void
    solve(const ArrayView<double> &rows) const;

    /// The operations of the last successful factorisation and of a
    /// substitution with it, as MUMPS counts them (the same on every
    /// rank); none before one.
    FactorCost
    cost() const;

  private:
    /**
     * One attempt of factorize(), with MUMPS's work space as its analysis
     * estimates it plus @p work_space_margin per cent (ICNTL(14), set when
     * the matrix's pattern is new or the last attempt failed). Returns 0,
     * or MUMPS's code for too small a work space unless this is the
     * @p last attempt; throws as factorize() otherwise.
     */
    PetscInt
    try_factorize(const PETScWrappers::MPI::SparseMatrix &matrix,
                  const std::vector<IndexSet>            &owned_per_rank,
                  const int                               work_space_margin,
                  const bool                              last);

    const bool   symmetric;
    const double block_low_rank_tolerance;
    FactorCost   last_cost;
    /// PETSc's solver state, behind a pointer to keep its headers out.
    struct Solver;
    std::unique_ptr<Solver> solver;
  };
} // namespace thinlayer

#endif
