// The thinlayer program; all of its work is in the core library.
#include <deal.II/base/mpi.h>

#include <thinlayer/app/command_line.h>
#include <thinlayer/parallel/mpi.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>

#include <unistd.h>

namespace
{
  /**
   * deal.II reads DEAL_II_NUM_THREADS while its library is loaded, before
   * main(): "abc" or "0" end the process there with an uncaught exception
   * (abort), and "-5" becomes some four billion threads. So the variable is
   * checked before any library is initialised (from .preinit_array, which
   * runs first), and a value that is not a whole number from 1 to 4096 ends
   * the program with a message and the status of a bad command line. Only
   * the loader's environment, write() and _exit() are used: nothing else is
   * ready.
   */
  void
  check_environment(int, char **, char **environment)
  {
    // The C library's own view of the environment (getenv()) is not set up
    // yet: the loader's is the third argument.
    const char *name  = "DEAL_II_NUM_THREADS=";
    const char *value = nullptr;
    for (char **e = environment; e != nullptr && *e != nullptr; ++e)
      if (std::strncmp(*e, name, std::strlen(name)) == 0)
        value = *e + std::strlen(name);
    if (value == nullptr)
      return;
    const std::size_t n       = std::strlen(value);
    unsigned long     threads = 0;
    bool              valid   = n > 0 && n <= 4;
    for (std::size_t i = 0; valid && i < n; ++i)
      {
        valid   = value[i] >= '0' && value[i] <= '9';
        threads = 10 * threads + (value[i] - '0');
      }
    if (valid && threads >= 1 && threads <= 4096)
      return;
    const auto say = [](const char *text) {
      if (::write(STDERR_FILENO, text, std::strlen(text)) < 0)
        _exit(2);
    };
    say("thinlayer: the environment variable DEAL_II_NUM_THREADS is '");
    say(value);
    say("'; expected a whole number of threads from 1 to 4096, or the "
        "variable unset (all cores)\n");
    _exit(2);
  }

  __attribute__((section(".preinit_array"),
                 used)) void (*const preinit)(int,
                                              char **,
                                              char **) = &check_environment;

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
