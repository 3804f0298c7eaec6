#ifndef thinlayer_base_interruption_h
#define thinlayer_base_interruption_h

#include <stdexcept>
#include <string>

namespace thinlayer
{
  /**
   * A signal stopped the program before a run had anything to write (while
   * gmsh was meshing): the command line exits with 128 + the signal, and
   * the results directory keeps the previous run.
   */
  class Interrupted : public std::runtime_error
  {
  public:
    explicit Interrupted(const std::string &where)
      : std::runtime_error("interrupted " + where + "; nothing was written")
    {}
  };


  /**
   * SIGINT and SIGTERM end a run as a result, not as a loss: while a
   * ScopedInterruption lives, the first such signal is only noted, the
   * solution methods stop their iterations, and the run is written with
   * `outcome: interrupted` and what it completed. Another signal two or
   * more seconds later ends the program at once; the results directory
   * then still holds the previous run (ResultsDirectory).
   */
  class ScopedInterruption
  {
  public:
    /// Install the handlers (the previous ones are restored on exit).
    ScopedInterruption();
    ~ScopedInterruption();

    ScopedInterruption(const ScopedInterruption &) = delete;
    ScopedInterruption &
    operator=(const ScopedInterruption &) = delete;
  };

  /**
   * The signal that asked the run to stop, or 0. On many ranks the largest
   * of every rank's, asked of all of them (a collective call: every rank
   * polls at the same points of the run, so all stop together).
   */
  int
  interruption_signal();

  /// This process's signal alone, or 0: for a loop that runs on one rank
  /// (waiting for gmsh).
  int
  local_interruption_signal();

  /// Whether a signal asked the run to stop: polled between iterations.
  inline bool
  interrupted()
  {
    return interruption_signal() != 0;
  }
} // namespace thinlayer

#endif
