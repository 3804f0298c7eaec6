#ifndef thinlayer_app_command_line_h
#define thinlayer_app_command_line_h

#include <ostream>
#include <string>
#include <vector>

namespace thinlayer
{
  /**
   * The thinlayer program: `thinlayer FILE.prm [-s "Section/Entry=value"]...`,
   * `thinlayer --print-parameters`, `thinlayer --help`. Results and progress
   * go to @p out, errors to @p err.
   *
   * Kept apart from main() so tests can run the whole program in-process.
   *
   * @return the exit status: 0 on success (a run that did not converge is a
   * result, not an error), 1 for bad input or results that could not be
   * written, 2 for a bad command line, 3 for an internal error, 128 + the
   * signal for a run that SIGINT or SIGTERM interrupted (its results are
   * written, `outcome: interrupted`).
   */
  int
  run_command_line(const std::vector<std::string> &arguments,
                   std::ostream                   &out,
                   std::ostream                   &err);
} // namespace thinlayer

#endif
