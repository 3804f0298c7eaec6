#include <deal.II/lac/petsc_vector.h>

#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/distributed_factorisation.h>

#include <stdexcept>

#include <petscksp.h>

namespace thinlayer
{
  struct DistributedFactorisation::Solver
  {
    KSP ksp = nullptr;
    /// The right-hand side and solution in PETSc's layout.
    mutable PETScWrappers::MPI::Vector rhs, solution;

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
    solver              = std::make_unique<Solver>();
    const MPI_Comm comm = mpi::communicator();
    solver->rhs.reinit(owned_per_rank[mpi::rank()], comm);
    solver->solution.reinit(owned_per_rank[mpi::rank()], comm);
    // The rows are contiguous and in rank order (number_dofs_by_rank()).
    counts.assign(owned_per_rank.size(), 0);
    offsets.assign(owned_per_rank.size(), 0);
    for (unsigned int r = 0; r < owned_per_rank.size(); ++r)
      {
        counts[r]  = static_cast<int>(owned_per_rank[r].n_elements());
        offsets[r] = r > 0 ? offsets[r - 1] + counts[r - 1] : 0;
      }

    Mat A = matrix;
    if (symmetric)
      MatSetOption(A, MAT_SPD, PETSC_TRUE);
    PetscErrorCode ierr = KSPCreate(comm, &solver->ksp);
    AssertThrow(ierr == 0, ExcPETScError(ierr));
    KSPSetOperators(solver->ksp, A, A);
    KSPSetType(solver->ksp, KSPPREONLY);
    PC pc;
    KSPGetPC(solver->ksp, &pc);
    PCSetType(pc, symmetric ? PCCHOLESKY : PCLU);
    PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
    // A singular matrix is an answer (a mechanism, missing supports), not
    // an error for PETSc to print: it is read off the preconditioner.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    ierr = KSPSetUp(solver->ksp);
    PetscPopErrorHandler();
    PCFailedReason reason = PC_NOERROR;
    PCGetFailedReason(pc, &reason);
    const bool failed =
      Utilities::MPI::max(ierr != 0 || reason != PC_NOERROR ? 1 : 0, comm) == 1;
    if (failed)
      {
        solver.reset();
        throw std::runtime_error("MUMPS: the matrix is singular");
      }
  }


  void
  DistributedFactorisation::solve(Vector<double> &rhs) const
  {
    Assert(solver, ExcMessage("factorize() first."));
    const unsigned int me    = mpi::rank();
    const std::size_t  first = offsets[me];
    {
      PetscScalar *b;
      VecGetArray(solver->rhs, &b);
      for (int i = 0; i < counts[me]; ++i)
        b[i] = rhs[first + i];
      VecRestoreArray(solver->rhs, &b);
    }
    KSPSolve(solver->ksp, solver->rhs, solver->solution);

    // Every rank's rows of the solution, to every rank.
    const PetscScalar *x;
    VecGetArrayRead(solver->solution, &x);
    const int ierr = MPI_Allgatherv(x,
                                    counts[me],
                                    MPI_DOUBLE,
                                    rhs.data(),
                                    counts.data(),
                                    offsets.data(),
                                    MPI_DOUBLE,
                                    mpi::communicator());
    VecRestoreArrayRead(solver->solution, &x);
    AssertThrowMPI(ierr);
  }
} // namespace thinlayer
