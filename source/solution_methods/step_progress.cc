#include <thinlayer/base/text_format.h>
#include <thinlayer/solution_methods/step_progress.h>

namespace thinlayer
{
  namespace
  {
    /// The open reporter, if any (load steps run on the main thread).
    StepProgress *current = nullptr;
  } // namespace


  StepProgress::StepProgress(std::ostream      &out,
                             const unsigned int step,
                             const double       load_factor,
                             const double       interval)
    : out(out)
    , step(step)
    , load_factor(load_factor)
    , interval(interval)
    , start(std::chrono::steady_clock::now())
    , next_line(start +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                  this->interval))
  {
    current = interval > 0 ? this : nullptr;
  }


  StepProgress::~StepProgress()
  {
    current = nullptr;
  }


  void
  report_iteration(const unsigned int iteration,
                   const char        *measure,
                   const double       value)
  {
    if (current == nullptr)
      return;
    const auto now = std::chrono::steady_clock::now();
    if (now < current->next_line)
      return;
    current->next_line =
      now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
              current->interval);
    current->out << "  step " << text_format::printf("%4.0f", current->step)
                 << "  load factor "
                 << text_format::printf("%10.6g", current->load_factor)
                 << "  ... iteration " << iteration << ", " << measure << ' '
                 << text_format::printf("%.3e", value) << " after "
                 << std::chrono::duration_cast<std::chrono::seconds>(
                      now - current->start)
                      .count()
                 << " s" << std::endl;
  }
} // namespace thinlayer
