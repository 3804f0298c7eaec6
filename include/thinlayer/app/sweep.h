#ifndef thinlayer_app_sweep_h
#define thinlayer_app_sweep_h

#include <thinlayer/parameters/parameters.h>

#include <ostream>
#include <string>
#include <vector>

namespace thinlayer
{
  /// What the program's exit status is made of: runs that ended in an
  /// error, and runs that missed the truth their Reference section names.
  struct SweepResult
  {
    unsigned int failed_runs       = 0;
    unsigned int missed_references = 0;
  };

  /**
   * Run the scene of @p file once for every combination of the value lists
   * in its Sweep section (a cartesian product), each run in run-NNN of the
   * output directory, and write sweep.csv there: one row per run with the
   * swept values and the main figures of its summary. Every combination's
   * parameters are checked before the first run; a run that fails (no
   * convergence, or a geometry gmsh cannot mesh) is a row, not an abort.
   * The sweep's directory, like a run's, is written aside and put in place
   * at the end (ResultsDirectory); a signal ends the sweep after the run
   * it interrupted.
   *
   * @param file      the parameter file, named in errors and in each run's
   *                  record.
   * @param overrides the command line's overrides, applied to every run.
   * @param base      the parameters as read without the sweep.
   * @param out       where the progress of the runs goes.
   * @return how many runs ended in an error (not in non-convergence, which
   * is a result) and how many missed what the Reference section expects:
   * the program then exits non-zero.
   */
  SweepResult
  run_sweep(const std::string              &file,
            const std::vector<std::string> &overrides,
            const Parameters               &base,
            std::ostream                   &out);
} // namespace thinlayer

#endif
