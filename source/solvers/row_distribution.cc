#include <deal.II/lac/exceptions.h>

#include <thinlayer/solvers/row_distribution.h>

#include <algorithm>

namespace thinlayer
{
  RowDistribution::~RowDistribution()
  {
    for (Vec *v : {&rhs, &solution})
      if (*v != nullptr)
        VecDestroy(v);
  }


  void
  RowDistribution::reinit(const std::vector<IndexSet> &owned_per_rank,
                          const MPI_Comm               communicator)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    n_rows                  = owned_per_rank[rank].n_elements();
    for (Vec *v : {&rhs, &solution})
      {
        if (*v != nullptr)
          VecDestroy(v);
        const PetscErrorCode ierr =
          VecCreateMPI(communicator, n_rows, PETSC_DETERMINE, v);
        AssertThrow(ierr == 0, ExcPETScError(ierr));
      }
  }


  void
  RowDistribution::scatter(const ArrayView<const double> &rows) const
  {
    AssertDimension(rows.size(), static_cast<std::size_t>(n_rows));
    PetscScalar *b;
    VecGetArray(rhs, &b);
    std::copy(rows.begin(), rows.end(), b);
    VecRestoreArray(rhs, &b);
  }


  void
  RowDistribution::gather(const ArrayView<double> &rows) const
  {
    AssertDimension(rows.size(), static_cast<std::size_t>(n_rows));
    const PetscScalar *x;
    VecGetArrayRead(solution, &x);
    std::copy(x, x + n_rows, rows.begin());
    VecRestoreArrayRead(solution, &x);
  }
} // namespace thinlayer
