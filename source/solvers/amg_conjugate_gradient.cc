#include <deal.II/lac/exceptions.h>

#include <thinlayer/base/text_format.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/amg_conjugate_gradient.h>
#include <thinlayer/solvers/linear_solver_failure.h>
#include <thinlayer/solvers/row_distribution.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <petscksp.h>

namespace thinlayer
{
  struct AmgConjugateGradient::Solver
  {
    KSP          ksp             = nullptr;
    MatNullSpace near_null_space = nullptr;
    /// The matrix with its block size (the unknowns of a node).
    Mat matrix = nullptr;
    /// The right-hand side and solution in PETSc's layout.
    RowDistribution rows;

    ~Solver()
    {
      if (ksp != nullptr)
        KSPDestroy(&ksp);
      if (near_null_space != nullptr)
        MatNullSpaceDestroy(&near_null_space);
      if (matrix != nullptr)
        MatDestroy(&matrix);
    }
  };


  namespace
  {
    /**
     * A copy of @p A whose block size is @p block_size: PETSc's smoothed
     * aggregation groups the unknowns of a node by it, and without it
     * aggregates single unknowns, on which the rigid motions are no
     * near-null space (1400 CG iterations on Prandtl's footing at 23k
     * unknowns where the blocked matrix takes 30). deal.II's PETSc
     * matrices have block size 1, fixed once allocated.
     */
    Mat
    blocked_copy(const Mat A, const PetscInt block_size)
    {
      PetscInt first, last, n_rows, n_columns;
      MatGetOwnershipRange(A, &first, &last);
      MatGetSize(A, &n_rows, &n_columns);
      std::vector<PetscInt> diagonal(last - first), off_diagonal(last - first);
      for (PetscInt i = first; i < last; ++i)
        {
          PetscInt        n_entries;
          const PetscInt *columns;
          MatGetRow(A, i, &n_entries, &columns, nullptr);
          for (PetscInt k = 0; k < n_entries; ++k)
            ++(columns[k] >= first && columns[k] < last
                 ? diagonal[i - first]
                 : off_diagonal[i - first]);
          MatRestoreRow(A, i, &n_entries, &columns, nullptr);
        }
      MPI_Comm comm;
      PetscObjectGetComm(reinterpret_cast<PetscObject>(A), &comm);
      Mat B;
      MatCreate(comm, &B);
      MatSetSizes(B, last - first, last - first, n_rows, n_columns);
      MatSetBlockSize(B, block_size);
      MatSetType(B, MATAIJ);
      MatSeqAIJSetPreallocation(B, 0, diagonal.data());
      MatMPIAIJSetPreallocation(B, 0, diagonal.data(), 0, off_diagonal.data());
      for (PetscInt i = first; i < last; ++i)
        {
          PetscInt           n_entries;
          const PetscInt    *columns;
          const PetscScalar *values;
          MatGetRow(A, i, &n_entries, &columns, &values);
          MatSetValues(B, 1, &i, n_entries, columns, values, INSERT_VALUES);
          MatRestoreRow(A, i, &n_entries, &columns, &values);
        }
      MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY);
      MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY);
      return B;
    }
  } // namespace


  AmgConjugateGradient::AmgConjugateGradient(const double relative_tolerance,
                                             const unsigned int max_iterations)
    : relative_tolerance(relative_tolerance)
    , max_iterations(max_iterations)
  {}


  AmgConjugateGradient::~AmgConjugateGradient() = default;


  void
  AmgConjugateGradient::initialize(
    const PETScWrappers::MPI::SparseMatrix &matrix,
    const std::vector<IndexSet>            &owned_per_rank,
    const std::vector<Vector<double>>      &near_null_space,
    const unsigned int                      block_size)
  {
    solver                = std::make_unique<Solver>();
    const MPI_Comm  comm  = matrix.get_mpi_communicator();
    const unsigned  me    = mpi::rank();
    const IndexSet &owned = owned_per_rank[me];
    solver->rows.reinit(owned_per_rank, comm);

    // The near-null space, orthonormalised (PETSc asks for it) by modified
    // Gram-Schmidt, each rank on its rows, the products summed.
    // deal.II's vector operations refuse empty vectors: a rank may own
    // no rows.
    const bool rows = owned.n_elements() > 0;
    const auto dot  = [rows](const Vector<double> &a, const Vector<double> &b) {
      return mpi::sum(rows ? a * b : 0.);
    };
    std::vector<Vector<double>> basis;
    for (const Vector<double> &v : near_null_space)
      {
        Vector<double> w = v;
        for (const Vector<double> &b : basis)
          if (rows)
            w.add(-dot(w, b), b);
          else
            dot(w, b);
        const double norm = std::sqrt(dot(w, w));
        if (norm > 1e-10 * std::sqrt(dot(v, v)) && norm > 0)
          {
            if (rows)
              w /= norm;
            basis.push_back(std::move(w));
          }
      }
    std::vector<Vec> vecs(basis.size());
    for (unsigned int k = 0; k < basis.size(); ++k)
      {
        VecCreateMPI(comm, owned.n_elements(), PETSC_DETERMINE, &vecs[k]);
        PetscScalar *x;
        VecGetArray(vecs[k], &x);
        for (unsigned int i = 0; i < owned.n_elements(); ++i)
          x[i] = basis[k][i];
        VecRestoreArray(vecs[k], &x);
      }
    solver->matrix      = blocked_copy(matrix, block_size);
    Mat            A    = solver->matrix;
    PetscErrorCode ierr = MatNullSpaceCreate(
      comm, PETSC_FALSE, vecs.size(), vecs.data(), &solver->near_null_space);
    for (Vec &v : vecs) // the null space holds its own references
      VecDestroy(&v);
    AssertThrow(ierr == 0, ExcPETScError(ierr));
    MatSetNearNullSpace(A, solver->near_null_space);
    MatSetOption(A, MAT_SPD, PETSC_TRUE);

    ierr = KSPCreate(comm, &solver->ksp);
    AssertThrow(ierr == 0, ExcPETScError(ierr));
    KSPSetOperators(solver->ksp, A, A);
    KSPSetType(solver->ksp, KSPCG);
    KSPSetNormType(solver->ksp, KSP_NORM_UNPRECONDITIONED);
    KSPSetTolerances(solver->ksp,
                     relative_tolerance,
                     /*absolute=*/1e-300,
                     PETSC_DEFAULT,
                     max_iterations);
    PC pc;
    KSPGetPC(solver->ksp, &pc);
    PCSetType(pc, PCGAMG);
    PCGAMGSetType(pc, PCGAMGAGG);
    // PETSc's options (PETSC_OPTIONS in the environment) tune the rest:
    // -pc_gamg_threshold, -mg_levels_ksp_max_it, -ksp_monitor, ...
    KSPSetFromOptions(solver->ksp);
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    ierr = KSPSetUp(solver->ksp);
    PetscPopErrorHandler();
    if (Utilities::MPI::max(ierr != 0 ? 1 : 0, comm) == 1)
      {
        solver.reset();
        throw LinearSolverFailure("PETSc could not build the algebraic "
                                  "multigrid preconditioner (PETSc error " +
                                  std::to_string(ierr) + ")");
      }
  }


  void
  AmgConjugateGradient::solve(const ArrayView<double> &rows) const
  {
    Assert(solver, ExcMessage("initialize() first."));
    solver->rows.scatter(rows);
    KSPSolve(solver->ksp, solver->rows.rhs, solver->rows.solution);
    KSPConvergedReason reason;
    KSPGetConvergedReason(solver->ksp, &reason);
    PetscInt n_iterations = 0;
    KSPGetIterationNumber(solver->ksp, &n_iterations);
    iterations += n_iterations;
    ++solves;
    // The right-hand side of zero converges at once; any other reason
    // below zero is a failure (the iteration limit, a breakdown).
    if (reason < 0)
      {
        PetscReal residual = 0;
        KSPGetResidualNorm(solver->ksp, &residual);
        throw LinearSolverFailure(
          "AMG-preconditioned CG did not converge: " +
          std::to_string(n_iterations) + " iterations, residual " +
          text_format::printf("%.3e", residual) + " (PETSc's reason " +
          std::to_string(reason) +
          "); raise Solver/Linear solver iterations or use a direct solver");
      }

    solver->rows.gather(rows);
  }


  unsigned long
  AmgConjugateGradient::total_iterations() const
  {
    return iterations;
  }


  unsigned long
  AmgConjugateGradient::n_solves() const
  {
    return solves;
  }


  std::unique_ptr<PETScWrappers::MPI::SparseMatrix>
  petsc_copy(const SparseMatrix<double> &matrix)
  {
    mpi::start_petsc();
    const IndexSet rows = complete_index_set(matrix.m());
    auto           copy = std::make_unique<PETScWrappers::MPI::SparseMatrix>();
    copy->reinit(rows, rows, matrix.get_sparsity_pattern(), MPI_COMM_SELF);
    for (unsigned int i = 0; i < matrix.m(); ++i)
      for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        copy->set(i, entry->column(), entry->value());
    copy->compress(VectorOperation::insert);
    return copy;
  }
} // namespace thinlayer
