// The thinlayer program; all of its work is in the core library.
#include <deal.II/base/mpi.h>

#include <thinlayer/app/command_line.h>
#include <thinlayer/parallel/mpi.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>

namespace
{
  /// Whether an MPI launcher (mpirun of Open MPI or MPICH, srun) started
  /// this process: each sets one of these.
  bool
  under_mpi_launcher()
  {
    for (const char *name :
         {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }
} // namespace


int
main(int argc, char **argv)
{
  // Under mpirun, as many processes as it starts, each with its share of
  // the node's cores as threads. Without it, MPI is not started at all: a
  // run is then the one-process program it always was (MPI's start-up
  // alone costs about a second), and every thinlayer::mpi function is the
  // identity. MPI (and PETSc, which deal.II starts with it) see none of
  // the arguments: they are ours, and PETSc would take --help for itself.
  std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi_session;
  int                                                       mpi_argc = 1;
  if (under_mpi_launcher())
    mpi_session =
      std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(mpi_argc,
                                                                 argv);
  // Rank 0 prints; the others' screen output is the same, and dropped.
  std::ostringstream quiet;
  return thinlayer::run_command_line(std::vector<std::string>(argv + 1,
                                                              argv + argc),
                                     thinlayer::mpi::is_root() ? std::cout
                                                               : quiet,
                                     std::cerr);
}
