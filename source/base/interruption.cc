#include <deal.II/base/mpi.h>

#include <thinlayer/base/interruption.h>

#include <csignal>
#include <ctime>

namespace thinlayer
{
  using namespace dealii;

  namespace
  {
    volatile std::sig_atomic_t received_signal = 0;
    /// When the first signal came (CLOCK_MONOTONIC seconds).
    volatile std::sig_atomic_t first_signal_time = 0;

    struct sigaction previous_interrupt, previous_terminate;

    std::sig_atomic_t
    now()
    {
      timespec t;
      clock_gettime(CLOCK_MONOTONIC, &t); // async-signal-safe
      return static_cast<std::sig_atomic_t>(t.tv_sec);
    }

    extern "C" void
    note_signal(const int signal)
    {
      if (received_signal == 0)
        {
          received_signal   = signal;
          first_signal_time = now();
          return;
        }
      // Another one seconds later ends the program: a user who insists
      // gets out. One that comes with the first (timeout(1) signals the
      // process and then its group; Ctrl-C reaches every process of the
      // terminal's group) is the same request.
      if (now() - first_signal_time >= 2)
        {
          std::signal(signal, SIG_DFL);
          std::raise(signal);
        }
    }
  } // namespace


  ScopedInterruption::ScopedInterruption()
  {
    received_signal         = 0;
    first_signal_time       = 0;
    struct sigaction action = {};
    action.sa_handler       = note_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_interrupt);
    sigaction(SIGTERM, &action, &previous_terminate);
  }


  ScopedInterruption::~ScopedInterruption()
  {
    sigaction(SIGINT, &previous_interrupt, nullptr);
    sigaction(SIGTERM, &previous_terminate, nullptr);
  }


  int
  interruption_signal()
  {
    // Every rank must stop at the same iteration: the largest signal of
    // any rank, asked of all of them.
    const int signal = received_signal;
    if (Utilities::MPI::job_supports_mpi() &&
        Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
      return Utilities::MPI::max(signal, MPI_COMM_WORLD);
    return signal;
  }


  int
  local_interruption_signal()
  {
    return received_signal;
  }
} // namespace thinlayer
