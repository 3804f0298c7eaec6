#include <deal.II/lac/exceptions.h>

#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/distributed_factorisation.h>
#include <thinlayer/solvers/linear_solver_failure.h>
#include <thinlayer/solvers/row_distribution.h>

#include <stdexcept>

#include <petscksp.h>
#include <petscmat.h>

namespace thinlayer
{
  struct DistributedFactorisation::Solver
  {
    KSP ksp = nullptr;
    /// The matrix the KSP was set up with: a next factorisation of it
    /// (Newton's tangent, same pattern, new values) reuses MUMPS's
    /// symbolic analysis.
    Mat matrix = nullptr;
    /// The right-hand side and solution in PETSc's layout.
    RowDistribution rows;

    ~Solver()
    {
      if (ksp != nullptr)
        KSPDestroy(&ksp);
    }
  };


  DistributedFactorisation::DistributedFactorisation(const bool symmetric)
    : symmetric(symmetric)
  {}


  DistributedFactorisation::~DistributedFactorisation() = default;


  void
  DistributedFactorisation::factorize(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const std::vector<IndexSet>            &owned_per_rank)
  {
    const MPI_Comm comm = mpi::communicator();
    Mat            A    = matrix;
    PetscErrorCode ierr = 0;
    PC             pc;
    if (solver && solver->matrix == A)
      {
        // The same matrix with new values: PETSc sees them changed and
        // redoes only the numerical factorisation.
        KSPSetOperators(solver->ksp, A, A);
        KSPGetPC(solver->ksp, &pc);
      }
    else
      {
        solver         = std::make_unique<Solver>();
        solver->matrix = A;
        solver->rows.reinit(owned_per_rank, comm);

        if (symmetric)
          MatSetOption(A, MAT_SPD, PETSC_TRUE);
        ierr = KSPCreate(comm, &solver->ksp);
        AssertThrow(ierr == 0, ExcPETScError(ierr));
        KSPSetOperators(solver->ksp, A, A);
        KSPSetType(solver->ksp, KSPPREONLY);
        KSPGetPC(solver->ksp, &pc);
        PCSetType(pc, symmetric ? PCCHOLESKY : PCLU);
        PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
        PCFactorSetUpMatSolverType(pc);
        Mat new_factor = nullptr;
        PCFactorGetMatrix(pc, &new_factor);
        // Null pivots detected (ICNTL(24)), counted in INFOG(28): a pivot
        // below MUMPS's threshold is round-off of a singular matrix (a
        // mechanism, interface elements too soft for the cells beside
        // them), which L D L^T would otherwise divide by without complaint.
        MatMumpsSetIcntl(new_factor, 24, 1);
      }
    Mat factor = nullptr;
    PCFactorGetMatrix(pc, &factor);
    // A singular matrix is an answer (a mechanism, missing supports), not
    // an error for PETSc to print: it is read off the preconditioner.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    ierr = KSPSetUp(solver->ksp);
    PetscPopErrorHandler();
    PCFailedReason reason = PC_NOERROR;
    PCGetFailedReason(pc, &reason);
    // MUMPS's own code (INFOG(1), the same on every rank): -10 is a
    // numerically singular matrix; others are failures of the solver.
    // A matrix meant to be positive definite with a negative pivot
    // (INFOG(12)) is singular up to round-off: CHOLMOD on one rank finds it
    // not positive definite.
    PetscInt error_code = 0, singular_pivots = 0, negative_pivots = 0;
    MatMumpsGetInfog(factor, 1, &error_code);
    if (error_code >= 0)
      {
        MatMumpsGetInfog(factor, 28, &singular_pivots); // null pivots
        if (symmetric)
          MatMumpsGetInfog(factor, 12, &negative_pivots);
        singular_pivots += negative_pivots;
      }
    const bool failed = Utilities::MPI::max(ierr != 0 || reason != PC_NOERROR ||
                                                singular_pivots > 0
                                              ? 1
                                              : 0,
                                            comm) == 1;
    if (failed)
      {
        solver.reset();
        const bool singular = error_code == -10 || singular_pivots > 0 ||
                              reason == PC_FACTOR_NUMERIC_ZEROPIVOT ||
                              reason == PC_FACTOR_STRUCT_ZEROPIVOT;
        if (singular)
          throw SingularMatrix("MUMPS: the matrix is singular");
        throw LinearSolverFailure(
          "MUMPS could not factorise the stiffness matrix (its error code "
          "INFOG(1) = " +
          std::to_string(error_code) +
          "; -8, -9, -13 and -19 mean too little memory, -38 a parallel "
          "ordering this build of MUMPS lacks)");
      }
  }


  void
  DistributedFactorisation::solve(Vector<double> &rhs) const
  {
    Assert(solver, ExcMessage("factorize() first."));
    solver->rows.scatter(rhs);
    KSPSolve(solver->ksp, solver->rows.rhs, solver->rows.solution);
    solver->rows.gather(rhs);
  }
} // namespace thinlayer
