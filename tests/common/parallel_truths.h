// What a unit test run on several ranks prints for a truth every rank
// checks: rank 0 prints whether it held on all of them.
#ifndef thinlayer_tests_parallel_truths_h
#define thinlayer_tests_parallel_truths_h

#include <deal.II/base/mpi.h>

#include <thinlayer/parallel/mpi.h>

#include <cstdio>
#include <string>

#include "truths.h"

namespace truths
{
  /// For a test every rank runs alike: only rank 0's standard output is
  /// kept (the others' goes to /dev/null). False if that fails.
  inline bool
  print_on_rank_zero()
  {
    return thinlayer::mpi::is_root() ||
           std::freopen("/dev/null", "w", stdout) != nullptr;
  }

  /// Whether @p holds on every rank, printed by rank 0; every rank counts
  /// a failure, so that every rank's exit status says it.
  inline void
  expect_everywhere(const bool holds, const std::string &what)
  {
    const bool all =
      dealii::Utilities::MPI::min(holds ? 1 : 0,
                                  thinlayer::mpi::communicator()) == 1;
    if (thinlayer::mpi::is_root())
      expect(all, what);
    else
      failures += all ? 0 : 1;
  }
} // namespace truths

#endif
