// What a unit test prints for each truth it asserts, and its exit status:
// a test fails on a truth that does not hold, whatever its reference output.
#ifndef thinlayer_tests_truths_h
#define thinlayer_tests_truths_h

#include <iostream>
#include <string>

namespace truths
{
  inline int failures = 0;

  /// One line: @p what, and whether it holds.
  inline void
  expect(const bool holds, const std::string &what)
  {
    std::cout << "  " << what << ": " << (holds ? "yes" : "NO") << '\n';
    failures += holds ? 0 : 1;
  }

  /// The last line, and the exit status: non-zero if any truth failed.
  inline int
  conclude()
  {
    std::cout << (failures == 0 ? "all truths hold\n" : "SOME TRUTHS FAIL\n");
    return failures == 0 ? 0 : 1;
  }
} // namespace truths

#endif
