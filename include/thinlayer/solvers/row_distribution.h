#ifndef thinlayer_solvers_row_distribution_h
#define thinlayer_solvers_row_distribution_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <vector>

#include <petscvec.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * A right-hand side and a solution in PETSc's layout for a matrix
   * distributed over the ranks by rows: each rank's contiguous range, in
   * rank order, which is also the range of DoFs a rank owns in a
   * ModeVector. The PETSc solvers take each rank's rows of the right-hand
   * side and give each rank its rows of the solution.
   *
   * The vectors are PETSc's own: deal.II's wrappers refuse to be made
   * while threads may run (deal.II's debug library asserts it), and
   * thinlayer touches PETSc from one thread only.
   */
  class RowDistribution
  {
  public:
    RowDistribution() = default;

    RowDistribution(const RowDistribution &) = delete;

    RowDistribution &
    operator=(const RowDistribution &) = delete;

    ~RowDistribution();

    /// Every rank's rows, @p owned_per_rank, on @p communicator; the
    /// vectors in PETSc's layout are sized for this rank's.
    void
    reinit(const std::vector<IndexSet> &owned_per_rank,
           const MPI_Comm               communicator);

    /// Copy this rank's @p rows of a right-hand side into its part of
    /// @p rhs.
    void
    scatter(const ArrayView<const double> &rows) const;

    /// This rank's part of @p solution, copied into its @p rows.
    void
    gather(const ArrayView<double> &rows) const;

    /// This rank's rows of a right-hand side and of a solution.
    Vec rhs = nullptr, solution = nullptr;

  private:
    PetscInt n_rows = 0;
  };
} // namespace thinlayer

#endif
