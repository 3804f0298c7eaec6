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
    owned               = owned_per_rank;
    solver              = std::make_unique<Solver>();
    const MPI_Comm comm = mpi::communicator();
    solver->rhs.reinit(owned[mpi::rank()], comm);
    solver->solution.reinit(owned[mpi::rank()], comm);

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
    const IndexSet &mine = owned[mpi::rank()];
    const auto      range =
      mine.n_elements() > 0
             ? std::make_pair(*mine.begin(), *mine.begin() + mine.n_elements())
             : std::make_pair(types::global_dof_index(0),
                         types::global_dof_index(0));
    {
      PetscScalar *b;
      VecGetArray(solver->rhs, &b);
      for (auto i = range.first; i < range.second; ++i)
        b[i - range.first] = rhs[i];
      VecRestoreArray(solver->rhs, &b);
    }
    KSPSolve(solver->ksp, solver->rhs, solver->solution);

    // Every rank's rows of the solution, to every rank.
    std::vector<int> counts(owned.size()), offsets(owned.size());
    for (unsigned int r = 0; r < owned.size(); ++r)
      {
        counts[r]  = static_cast<int>(owned[r].n_elements());
        offsets[r] = owned[r].n_elements() > 0
                       ? static_cast<int>(*owned[r].begin())
                       : (r > 0 ? offsets[r - 1] + counts[r - 1] : 0);
      }
    const PetscScalar *x;
    VecGetArrayRead(solver->solution, &x);
    const int ierr = MPI_Allgatherv(x,
                                    counts[mpi::rank()],
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
