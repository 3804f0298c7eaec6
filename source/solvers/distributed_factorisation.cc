#include <deal.II/lac/exceptions.h>

#include <thinlayer/base/work_counts.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/distributed_factorisation.h>
#include <thinlayer/solvers/linear_solver_failure.h>
#include <thinlayer/solvers/row_distribution.h>

#include <stdexcept>

#include <petscmat.h>

namespace thinlayer
{
  struct DistributedFactorisation::Solver
  {
    /// MUMPS's factor. It keeps no reference to the matrix it was
    /// factorised from: the caller may free that matrix (the elastic
    /// stiffness, factorised once) and keep only the factor.
    Mat factor = nullptr;
    /// PETSc's unique id of the matrix factorised last (ids, unlike
    /// addresses, are never reused): a next factorisation of the same
    /// matrix (Newton's tangent, same pattern, new values) redoes only the
    /// numerical factorisation.
    PetscInt64 matrix_id = -1;
    /// The right-hand side and solution in PETSc's layout.
    RowDistribution rows;
    /// Whether the last factorisation succeeded: the factor may be used.
    bool factorised = false;

    /// MUMPS's factor of @p A (of PETSc id @p id), not yet analysed, as
    /// factorize() asks for it.
    Solver(Mat                          A,
           const PetscInt64             id,
           const std::vector<IndexSet> &owned_per_rank,
           const bool                   symmetric,
           const double                 block_low_rank_tolerance,
           const int                    work_space_margin)
      : matrix_id(id)
    {
      rows.reinit(owned_per_rank, mpi::communicator());
      if (symmetric)
        MatSetOption(A, MAT_SPD, PETSC_TRUE);
      const PetscErrorCode ierr =
        MatGetFactor(A,
                     MATSOLVERMUMPS,
                     symmetric ? MAT_FACTOR_CHOLESKY : MAT_FACTOR_LU,
                     &factor);
      AssertThrow(ierr == 0, ExcPETScError(ierr));
      // Null pivots detected (ICNTL(24)), counted in INFOG(28): a pivot
      // below MUMPS's threshold is round-off of a singular matrix (a
      // mechanism, interface elements too soft for the cells beside
      // them), which L D L^T would otherwise divide by without complaint.
      MatMumpsSetIcntl(factor, 24, 1);
      // The margin (ICNTL(14), per cent) on MUMPS's estimate of its work
      // space: factorize() chooses it.
      MatMumpsSetIcntl(factor, 14, work_space_margin);
      // Block low-rank factorisation and solution (ICNTL(35) = 2), the
      // blocks' dropping threshold CNTL(7).
      if (block_low_rank_tolerance > 0)
        {
          MatMumpsSetIcntl(factor, 35, 2);
          MatMumpsSetCntl(factor, 7, block_low_rank_tolerance);
        }
    }

    ~Solver()
    {
      if (factor != nullptr)
        MatDestroy(&factor);
    }
  };


  namespace
  {
    /// MUMPS's codes for a work space that its analysis estimated too
    /// small (INFOG(1)): -8 and -14 integer, -9 real, -20 a reception
    /// buffer between ranks (met with block low-rank compression), each
    /// sized from the estimate and its margin.
    bool
    work_space_too_small(const PetscInt error_code)
    {
      return error_code == -8 || error_code == -9 || error_code == -14 ||
             error_code == -20;
    }
  } // namespace


  DistributedFactorisation::DistributedFactorisation(
    const bool   symmetric,
    const double block_low_rank_tolerance)
    : symmetric(symmetric)
    , block_low_rank_tolerance(block_low_rank_tolerance)
  {}


  DistributedFactorisation::~DistributedFactorisation() = default;


  void
  DistributedFactorisation::factorize(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const std::vector<IndexSet>            &owned_per_rank)
  {
    ++work_counts().factorisations;
    const WorkTimer timer(work_counts().factorisation_seconds);
    // Without pivoting (a positive definite matrix) MUMPS's estimate of its
    // work space is its need, up to its dynamic scheduling on several
    // ranks: its default margin of 20% is memory held for nothing, a fifth
    // of the factor's. Compression makes the estimate a guess: MUMPS's own
    // margin then.
    const int first_margin =
      symmetric && block_low_rank_tolerance == 0 ? 0 : 20;
    // Where the work space (or, compressed, the buffer between the ranks)
    // still ran short: once more with twice the estimate.
    if (work_space_too_small(
          try_factorize(matrix, owned_per_rank, first_margin, false)))
      try_factorize(matrix, owned_per_rank, 100, true);
  }


  PetscInt
  DistributedFactorisation::try_factorize(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const std::vector<IndexSet>            &owned_per_rank,
    const int                               work_space_margin,
    const bool                              last)
  {
    const MPI_Comm comm = mpi::communicator();
    Mat            A    = matrix;
    PetscInt64     id   = -1;
    PetscObjectGetId(reinterpret_cast<PetscObject>(A), &id);
    const bool new_pattern = !solver || solver->matrix_id != id;
    if (new_pattern)
      solver = std::make_unique<Solver>(A,
                                        id,
                                        owned_per_rank,
                                        symmetric,
                                        block_low_rank_tolerance,
                                        work_space_margin);

    // A singular matrix is an answer (a mechanism, missing supports), not
    // an error for PETSc to print: it is read off the factor.
    MatFactorInfo info;
    MatFactorInfoInitialize(&info);
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    PetscErrorCode ierr = 0;
    if (new_pattern)
      ierr =
        symmetric
          ? MatCholeskyFactorSymbolic(solver->factor, A, nullptr, &info)
          : MatLUFactorSymbolic(solver->factor, A, nullptr, nullptr, &info);
    if (ierr == 0)
      ierr = symmetric ? MatCholeskyFactorNumeric(solver->factor, A, &info)
                       : MatLUFactorNumeric(solver->factor, A, &info);
    PetscPopErrorHandler();
    MatFactorError factor_error = MAT_FACTOR_NOERROR;
    MatFactorGetError(solver->factor, &factor_error);

    // MUMPS's own code (INFOG(1), the same on every rank): -10 is a
    // numerically singular matrix; others are failures of the solver.
    // A matrix meant to be positive definite with a negative pivot
    // (INFOG(12)) is singular up to round-off: CHOLMOD on one rank finds it
    // not positive definite.
    PetscInt error_code = 0, singular_pivots = 0, negative_pivots = 0;
    MatMumpsGetInfog(solver->factor, 1, &error_code);
    if (error_code >= 0)
      {
        MatMumpsGetInfog(solver->factor, 28, &singular_pivots); // null pivots
        if (symmetric)
          MatMumpsGetInfog(solver->factor, 12, &negative_pivots);
        singular_pivots += negative_pivots;
      }
    // 2: MUMPS failed; 1: only the pivots show the matrix singular.
    const int verdict =
      Utilities::MPI::max(ierr != 0 || factor_error != MAT_FACTOR_NOERROR ||
                              error_code < 0
                            ? 2
                            : (singular_pivots > 0 ? 1 : 0),
                          comm);
    const bool mumps_failed = verdict == 2;
    const bool failed       = verdict > 0;
    solver->factorised      = !failed;
    if (!failed)
      {
        // RINFOG(3): the elimination's operations; INFOG(29): the factor's
        // entries (in millions where negative), each a multiply-add in one
        // triangular solve, or in two where L D L^T holds L alone.
        PetscReal flops   = 0;
        PetscInt  entries = 0;
        MatMumpsGetRinfog(solver->factor, 3, &flops);
        MatMumpsGetInfog(solver->factor, 29, &entries);
        const double n_entries = entries < 0 ? -1e6 * entries : entries;
        last_cost              = {flops, (symmetric ? 4 : 2) * n_entries};
        return 0;
      }
    // MUMPS's analysis stands when only the pivots showed the matrix
    // singular (Newton's tangent at a mechanism): the next factorisation
    // of the same matrix needs only new values. After MUMPS's own failure
    // it starts afresh.
    if (mumps_failed)
      solver.reset();
    if (!last && work_space_too_small(error_code))
      return error_code;
    const bool singular = error_code == -10 || singular_pivots > 0 ||
                          factor_error == MAT_FACTOR_NUMERIC_ZEROPIVOT ||
                          factor_error == MAT_FACTOR_STRUCT_ZEROPIVOT;
    if (singular)
      throw SingularMatrix("MUMPS: the matrix is singular");
    throw LinearSolverFailure(
      "MUMPS could not factorise the stiffness matrix (its error code "
      "INFOG(1) = " +
      std::to_string(error_code) +
      "; -8, -9, -13 and -19 mean too little memory, -38 a parallel "
      "ordering this build of MUMPS lacks)");
  }


  FactorCost
  DistributedFactorisation::cost() const
  {
    return solver && solver->factorised ? last_cost : FactorCost();
  }


  void
  DistributedFactorisation::solve(const ArrayView<double> &rows) const
  {
    ++work_counts().substitutions;
    Assert(solver && solver->factorised,
           ExcMessage("factorize() first, successfully."));
    solver->rows.scatter(rows);
    MatSolve(solver->factor, solver->rows.rhs, solver->rows.solution);
    solver->rows.gather(rows);
  }
} // namespace thinlayer
