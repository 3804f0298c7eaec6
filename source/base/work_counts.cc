#include <thinlayer/base/work_counts.h>

namespace thinlayer
{
  WorkCounts &
  work_counts()
  {
    static WorkCounts counts;
    return counts;
  }
} // namespace thinlayer
