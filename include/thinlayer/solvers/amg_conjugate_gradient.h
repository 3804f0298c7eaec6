#ifndef thinlayer_solvers_amg_conjugate_gradient_h
#define thinlayer_solvers_amg_conjugate_gradient_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/index_set.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The constant stiffness solved by conjugate gradients with an
   * algebraic multigrid preconditioner (PETSc's smoothed aggregation,
   * GAMG), the rigid-body motions as its near-null space: the solver whose
   * memory grows in proportion to the unknowns, for a scene whose factors
   * do not fit. Every solve costs a few dozen to hundreds of CG
   * iterations, where a substitution with the factors costs one pass, and
   * the count grows with a thin layer's stiffness contrast times its aspect
   * ratio (benchmarks/linear_solvers.py): the direct solvers are the choice
   * wherever their factors fit.
   *
   * As with DistributedFactorisation, the matrix is distributed by rows
   * (each rank its contiguous DoFs), and right-hand sides and solutions
   * are whole vectors on every rank.
   */
  class AmgConjugateGradient
  {
  public:
    /// CG stops at a residual of @p relative_tolerance times the
    /// right-hand side's, or fails after @p max_iterations.
    AmgConjugateGradient(const double       relative_tolerance,
                         const unsigned int max_iterations);

    ~AmgConjugateGradient();

    /**
     * Build the preconditioner of @p matrix, whose rows are distributed as
     * @p owned_per_rank says, with the vectors (on this rank's rows)
     * @p near_null_space: the motions the stiffness hardly resists, which
     * the coarse levels must represent. The unknowns come in nodes of
     * @p block_size, one after the other (1 where they do not). The
     * solver keeps a copy of the matrix with that block size, so
     * @p matrix may go after the call.
     */
    void
    initialize(const PETScWrappers::MPI::SparseMatrix &matrix,
               const std::vector<IndexSet>            &owned_per_rank,
               const std::vector<Vector<double>>      &near_null_space,
               const unsigned int                      block_size);

    /// Replace this rank's @p rows of a right-hand side by its rows of
    /// the solution of K x = rhs (a collective call). Throws
    /// LinearSolverFailure if CG does not converge (naming the iterations
    /// and the residual).
    void
    solve(const ArrayView<double> &rows) const;

    /// CG iterations of all solves so far.
    unsigned long
    total_iterations() const;

    /// Solves so far.
    unsigned long
    n_solves() const;

  private:
    const double       relative_tolerance;
    const unsigned int max_iterations;
    /// PETSc's solver state, behind a pointer to keep its headers out.
    struct Solver;
    std::unique_ptr<Solver> solver;
    mutable unsigned long   iterations = 0, solves = 0;
  };


  /**
   * A copy of @p matrix as a PETSc matrix on one process (starting PETSc
   * if no mpirun did), for the PETSc solvers on one rank.
   */
  std::unique_ptr<PETScWrappers::MPI::SparseMatrix>
  petsc_copy(const SparseMatrix<double> &matrix);
} // namespace thinlayer

#endif
