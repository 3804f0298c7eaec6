#ifndef thinlayer_solvers_row_distribution_h
#define thinlayer_solvers_row_distribution_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <vector>

#include <petscvec.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * How the rows of a matrix distributed over the ranks lie in the whole
   * vectors every rank holds: each rank's contiguous range, in rank order.
   * The PETSc solvers take each rank's rows of a whole right-hand side and
   * give every rank the whole solution.
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

    /// Copy this rank's rows of @p whole into its part of @p rhs().
    void
    scatter(const Vector<double> &whole) const;

    /// Every rank's part of solution(), gathered into @p whole on every
    /// rank.
    void
    gather(Vector<double> &whole) const;

    /// This rank's rows of a right-hand side and of a solution.
    Vec rhs = nullptr, solution = nullptr;

  private:
    MPI_Comm         communicator = MPI_COMM_SELF;
    std::vector<int> counts, offsets;
    unsigned int     rank = 0;
  };
} // namespace thinlayer

#endif
