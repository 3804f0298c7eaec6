#ifndef thinlayer_parallel_mpi_h
#define thinlayer_parallel_mpi_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The processes of a run: MPI_COMM_WORLD under mpirun, one process
   * without it (and in programs that never initialise MPI, such as the
   * unit tests, where every function here is the identity).
   *
   * Every rank runs the same control flow on the same data (the
   * parameters, the mesh, the load programme, every decision of the
   * stepping), and splits the work at the points: each rank runs the
   * point rules of the cells and interface elements it owns, and the
   * forces they produce are summed here. A sum reaches every rank with the
   * same bits (MPI's reductions combine in one order for all ranks), which
   * keeps the ranks' decisions identical.
   */
  namespace mpi
  {
    /// MPI_COMM_WORLD.
    MPI_Comm
    communicator();

    /// Start PETSc (and with it MPI, as a single process) if no mpirun
    /// did, for a PETSc solver on one rank; finalised at exit. Nothing if
    /// PETSc is running.
    void
    start_petsc();

    /// This process's rank, 0 without MPI.
    unsigned int
    rank();

    /// The number of ranks, 1 without MPI.
    unsigned int
    n_ranks();

    /// Whether this is rank 0, the one that reads, prints and writes what
    /// exists once.
    inline bool
    is_root()
    {
      return rank() == 0;
    }

    /**
     * The largest resident memory (VmRSS) of any rank now, in MB: taken
     * before the mesh is read, what the loaded program itself (libraries,
     * MPI) costs every rank, which no number of ranks divides.
     */
    double
    resident_memory_mb();

    /// The largest peak resident memory (VmHWM) of any rank, in MB.
    double
    peak_memory_mb();

    /// The largest over the ranks of @p value.
    double
    max(const double value);

    /// The sum over the ranks of @p value.
    unsigned int
    sum(const unsigned int value);

    /// The sum over the ranks of @p value.
    double
    sum(const double value);

    /// Replace @p v by its sum over the ranks; nothing on one rank.
    void
    sum(Vector<double> &v);

    /// Where each rank's part of a whole vector lies: every rank's count,
    /// and where it starts, in rank order.
    struct Parts
    {
      std::vector<int> counts, offsets;

      /// The size of the whole.
      std::size_t
      size() const
      {
        return counts.empty() ? 0 : offsets.back() + counts.back();
      }
    };

    /// The Parts of a whole of which this rank holds @p count entries (a
    /// collective call; kept by whoever gathers the same layout often).
    Parts
    parts(const std::size_t count);

    /// Every rank's @p part (laid out as @p parts), in rank order, as
    /// @p whole on every rank (resized): a distributed vector's owned parts
    /// made whole.
    void
    all_gather(const Parts                   &parts,
               const ArrayView<const double> &part,
               Vector<double>                &whole);

    /// The same on rank @p root only; @p whole is left alone elsewhere.
    void
    gather(const Parts                   &parts,
           const ArrayView<const double> &part,
           Vector<double>                &whole,
           const unsigned int             root);

    /// The inverse of gather(): each rank's @p part taken from rank
    /// @p root's @p whole.
    void
    scatter(const Parts             &parts,
            const Vector<double>    &whole,
            const ArrayView<double> &part,
            const unsigned int       root);

    /// Rank 0's @p text, on every rank.
    std::string
    broadcast(const std::string &text);

    /**
     * Rank 0 runs @p work (meshing with gmsh, opening the results
     * directory: what exists once), and its text reaches every rank. An
     * InputError or Interrupted that @p work throws is thrown on every
     * rank; any other error stays on rank 0, which ends all ranks
     * (abort_all()).
     */
    std::string
    on_root(const std::function<std::string()> &work);

    /**
     * End every rank with exit status @p status (MPI_Abort) when there are
     * several: for an error that only this rank has met, which the others,
     * waiting for it in a collective call, would otherwise wait for
     * forever. Returns on one rank.
     */
    void
    abort_all(const int status);
  } // namespace mpi
} // namespace thinlayer

#endif
