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
    this->communicator = communicator;
    rank               = Utilities::MPI::this_mpi_process(communicator);
    for (Vec *v : {&rhs, &solution})
      {
        if (*v != nullptr)
          VecDestroy(v);
        const PetscErrorCode ierr = VecCreateMPI(
          communicator, owned_per_rank[rank].n_elements(), PETSC_DETERMINE, v);
        AssertThrow(ierr == 0, ExcPETScError(ierr));
      }
    counts.assign(owned_per_rank.size(), 0);
    offsets.assign(owned_per_rank.size(), 0);
    for (unsigned int r = 0; r < owned_per_rank.size(); ++r)
      {
        counts[r]  = static_cast<int>(owned_per_rank[r].n_elements());
        offsets[r] = r > 0 ? offsets[r - 1] + counts[r - 1] : 0;
      }
  }


  void
  RowDistribution::scatter(const Vector<double> &whole) const
  {
    PetscScalar *b;
    VecGetArray(rhs, &b);
    std::copy(whole.begin() + offsets[rank],
              whole.begin() + offsets[rank] + counts[rank],
              b);
    VecRestoreArray(rhs, &b);
  }


  void
  RowDistribution::gather(Vector<double> &whole) const
  {
    const PetscScalar *x;
    VecGetArrayRead(solution, &x);
    const int ierr = MPI_Allgatherv(x,
                                    counts[rank],
                                    MPI_DOUBLE,
                                    whole.data(),
                                    counts.data(),
                                    offsets.data(),
                                    MPI_DOUBLE,
                                    communicator);
    VecRestoreArrayRead(solution, &x);
    AssertThrowMPI(ierr);
  }
} // namespace thinlayer
