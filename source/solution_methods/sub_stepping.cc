#include <thinlayer/solution_methods/sub_stepping.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  SubStepping::SubStepping(const double       start,
                           const double       end,
                           const unsigned int max_cut_backs)
    : end(end)
    , total(end - start)
    , max_cut_backs(max_cut_backs)
    , start(start)
    , size(end - start)
  {}


  bool
  SubStepping::last() const
  {
    return std::abs(start + size - end) <= 1e-12 * std::abs(total);
  }


  double
  SubStepping::target() const
  {
    // The end itself where the part reaches it, so that an uncut step
    // attempts exactly its own load factor.
    return last() ? end : start + size;
  }


  SubStepping::Next
  SubStepping::report(const bool converged)
  {
    if (converged)
      {
        if (last())
          return Next::done;
        const double reached = target();
        start                = reached;
        size                 = std::min(size, end - reached);
        return Next::next_part;
      }
    if (halvings == max_cut_backs)
      return Next::failed;
    ++halvings;
    size /= 2;
    return Next::retry;
  }


  unsigned int
  SubStepping::cut_backs() const
  {
    return halvings;
  }
} // namespace thinlayer
