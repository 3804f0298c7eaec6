#include <thinlayer/output/background_writer.h>

#include <utility>

namespace thinlayer
{
  BackgroundWriter::BackgroundWriter(const unsigned int max_pending)
    : max_pending(max_pending == 0 ? 1 : max_pending)
    , worker([this]() { work(); })
  {}


  BackgroundWriter::~BackgroundWriter()
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
    }
    changed.notify_all();
    worker.join();
  }


  void
  BackgroundWriter::submit(std::function<void()> job)
  {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [this]() { return error || jobs.size() < max_pending; });
    if (error)
      std::rethrow_exception(error);
    jobs.push_back(std::move(job));
    lock.unlock();
    changed.notify_all();
  }


  void
  BackgroundWriter::wait()
  {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [this]() { return jobs.empty() && !busy; });
    if (error)
      std::rethrow_exception(error);
  }


  bool
  BackgroundWriter::failed() const
  {
    std::lock_guard<std::mutex> lock(mutex);
    return static_cast<bool>(error);
  }


  void
  BackgroundWriter::rethrow_error() const
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (error)
      std::rethrow_exception(error);
  }


  void
  BackgroundWriter::work()
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (true)
      {
        changed.wait(lock, [this]() { return stopping || !jobs.empty(); });
        if (jobs.empty())
          return;
        std::function<void()> job = std::move(jobs.front());
        jobs.pop_front();
        busy = true;
        lock.unlock();
        std::exception_ptr job_error;
        try
          {
            job();
          }
        catch (...)
          {
            job_error = std::current_exception();
          }
        lock.lock();
        busy = false;
        if (job_error && !error)
          error = job_error;
        // The jobs after a failed one are dropped: their files would
        // follow one that is missing.
        if (error)
          jobs.clear();
        changed.notify_all();
      }
  }
} // namespace thinlayer
