#include <deal.II/base/utilities.h>
#include <deal.II/lac/exceptions.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/base/interruption.h>
#include <thinlayer/parallel/mpi.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include <petscsys.h>

namespace thinlayer
{
  namespace mpi
  {
    MPI_Comm
    communicator()
    {
      return MPI_COMM_WORLD;
    }


    void
    start_petsc()
    {
      PetscBool started = PETSC_FALSE;
      PetscInitialized(&started);
      if (started)
        return;
      const PetscErrorCode ierr = PetscInitializeNoArguments();
      AssertThrow(ierr == 0, ExcPETScError(ierr));
      // After every PETSc object (the analysis's) is gone.
      std::atexit([]() { PetscFinalize(); });
    }


    // deal.II's MPI queries call MPI itself, which must have been started:
    // a program without mpirun never starts it.
    unsigned int
    rank()
    {
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::this_mpi_process(communicator())
               : 0;
    }


    unsigned int
    n_ranks()
    {
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::n_mpi_processes(communicator())
               : 1;
    }


    double
    peak_memory_mb()
    {
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      return max(stats.VmHWM / 1024.);
    }


    double
    resident_memory_mb()
    {
      Utilities::System::MemoryStats stats;
      Utilities::System::get_memory_stats(stats);
      return max(stats.VmRSS / 1024.);
    }


    double
    max(const double value)
    {
      return n_ranks() == 1 ? value
                            : Utilities::MPI::max(value, communicator());
    }


    unsigned int
    sum(const unsigned int value)
    {
      return n_ranks() == 1 ? value
                            : Utilities::MPI::sum(value, communicator());
    }


    double
    sum(const double value)
    {
      return n_ranks() == 1 ? value
                            : Utilities::MPI::sum(value, communicator());
    }


    void
    sum(Vector<double> &v)
    {
      if (n_ranks() == 1 || v.size() == 0)
        return;
      const int ierr = MPI_Allreduce(MPI_IN_PLACE,
                                     v.data(),
                                     static_cast<int>(v.size()),
                                     MPI_DOUBLE,
                                     MPI_SUM,
                                     communicator());
      AssertThrowMPI(ierr);
    }


    Parts
    parts(const std::size_t count)
    {
      const int n = static_cast<int>(count);
      Parts     result;
      result.counts.assign(n_ranks(), n);
      if (n_ranks() > 1)
        {
          const int ierr = MPI_Allgather(
            &n, 1, MPI_INT, result.counts.data(), 1, MPI_INT, communicator());
          AssertThrowMPI(ierr);
        }
      result.offsets.assign(n_ranks(), 0);
      for (unsigned int r = 1; r < n_ranks(); ++r)
        result.offsets[r] = result.offsets[r - 1] + result.counts[r - 1];
      return result;
    }


    void
    all_gather(const Parts                   &parts,
               const ArrayView<const double> &part,
               Vector<double>                &whole)
    {
      AssertDimension(part.size(), parts.counts[rank()]);
      whole.reinit(parts.size(), /*omit_zeroing_entries=*/true);
      if (n_ranks() == 1)
        {
          std::copy(part.begin(), part.end(), whole.begin());
          return;
        }
      const int ierr = MPI_Allgatherv(part.data(),
                                      static_cast<int>(part.size()),
                                      MPI_DOUBLE,
                                      whole.data(),
                                      parts.counts.data(),
                                      parts.offsets.data(),
                                      MPI_DOUBLE,
                                      communicator());
      AssertThrowMPI(ierr);
    }


    void
    gather(const Parts                   &parts,
           const ArrayView<const double> &part,
           Vector<double>                &whole,
           const unsigned int             root)
    {
      if (n_ranks() == 1)
        {
          all_gather(parts, part, whole);
          return;
        }
      AssertDimension(part.size(), parts.counts[rank()]);
      if (rank() == root)
        whole.reinit(parts.size(), /*omit_zeroing_entries=*/true);
      const int ierr = MPI_Gatherv(part.data(),
                                   static_cast<int>(part.size()),
                                   MPI_DOUBLE,
                                   rank() == root ? whole.data() : nullptr,
                                   parts.counts.data(),
                                   parts.offsets.data(),
                                   MPI_DOUBLE,
                                   static_cast<int>(root),
                                   communicator());
      AssertThrowMPI(ierr);
    }


    void
    scatter(const Parts             &parts,
            const Vector<double>    &whole,
            const ArrayView<double> &part,
            const unsigned int       root)
    {
      AssertDimension(part.size(), parts.counts[rank()]);
      if (n_ranks() == 1)
        {
          std::copy(whole.begin(), whole.end(), part.begin());
          return;
        }
      const int ierr = MPI_Scatterv(rank() == root ? whole.data() : nullptr,
                                    parts.counts.data(),
                                    parts.offsets.data(),
                                    MPI_DOUBLE,
                                    part.data(),
                                    static_cast<int>(part.size()),
                                    MPI_DOUBLE,
                                    static_cast<int>(root),
                                    communicator());
      AssertThrowMPI(ierr);
    }


    std::string
    broadcast(const std::string &text)
    {
      if (n_ranks() == 1)
        return text;
      return Utilities::MPI::broadcast(communicator(), text, 0);
    }


    std::string
    on_root(const std::function<std::string()> &work)
    {
      if (n_ranks() == 1)
        return work();
      // The first character says what came: 't' text, 'i' an InputError
      // (file, entry and expectation separated by NUL), 's' an
      // interruption.
      if (is_root())
        {
          std::string text;
          try
            {
              text = work();
            }
          catch (const InputError &e)
            {
              broadcast('i' + e.file + '\0' + e.entry + '\0' + e.expected);
              throw;
            }
          catch (const Interrupted &e)
            {
              broadcast("s");
              throw;
            }
          broadcast('t' + text);
          return text;
        }
      const std::string message = broadcast("");
      if (message[0] == 'i')
        {
          const std::size_t a = message.find('\0', 1);
          const std::size_t b = message.find('\0', a + 1);
          throw InputError(message.substr(1, a - 1),
                           message.substr(a + 1, b - a - 1),
                           message.substr(b + 1));
        }
      if (message[0] == 's')
        throw Interrupted("on rank 0");
      return message.substr(1);
    }


    void
    abort_all(const int status)
    {
      if (n_ranks() == 1)
        return;
      std::cerr.flush();
      MPI_Abort(communicator(), status);
    }

  } // namespace mpi
} // namespace thinlayer
