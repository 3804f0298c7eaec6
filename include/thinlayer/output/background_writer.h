#ifndef thinlayer_output_background_writer_h
#define thinlayer_output_background_writer_h

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace thinlayer
{
  /**
   * Jobs that write files, run in order on one thread of their own, so
   * that the load stepping goes on while a step's fields are encoded
   * (zlib) and written. A job holds copies of everything it writes: the
   * analysis it came from may change as soon as it is submitted.
   *
   * At most @p max_pending jobs wait at a time: a submission beyond them
   * waits for the oldest to end, so that a scene whose fields take longer
   * to write than its steps to solve does not hold every step's fields in
   * memory at once.
   *
   * The first job that throws stops the ones after it; its exception is
   * thrown again by the next submit(), wait() or failed() that sees it,
   * on the submitting thread. The destructor waits for the jobs it holds
   * and swallows their errors (a run that is being unwound has its own).
   * No job may use MPI: the library is initialised for one thread.
   */
  class BackgroundWriter
  {
  public:
    explicit BackgroundWriter(unsigned int max_pending = 2);
    ~BackgroundWriter();

    BackgroundWriter(const BackgroundWriter &) = delete;
    BackgroundWriter &
    operator=(const BackgroundWriter &) = delete;

    /// Queue @p job behind the others; first rethrow an earlier job's
    /// error if there was one.
    void
    submit(std::function<void()> job);

    /// Block until every submitted job has ended; rethrow the first error.
    void
    wait();

    /// Whether a job has failed so far (without waiting for any).
    bool
    failed() const;

    /// Rethrow the first job's error, if there was one (without waiting).
    void
    rethrow_error() const;

  private:
    void
    work();

    unsigned int                      max_pending;
    mutable std::mutex                mutex;
    std::condition_variable           changed;
    std::deque<std::function<void()>> jobs;
    /// Whether the worker is running a job (taken off the queue).
    bool               busy     = false;
    bool               stopping = false;
    std::exception_ptr error;
    std::thread        worker;
  };
} // namespace thinlayer

#endif
