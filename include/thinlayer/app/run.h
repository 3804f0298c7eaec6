#ifndef thinlayer_app_run_h
#define thinlayer_app_run_h

#include <thinlayer/output/run_summary.h>
#include <thinlayer/parameters/parameters.h>

#include <ostream>

namespace thinlayer
{
  /**
   * Run one scene from its parameters: build the mesh, set up the analysis,
   * apply the load programme step by step and write history.csv, VTU/PVD
   * and summary.json into the output directory. Screen output is one line
   * per load step. All input is checked (InputError) before the output
   * directory is touched, and the run goes into place only when it ends
   * (ResultsDirectory): an error leaves the previous run, a signal
   * (ScopedInterruption) ends it with `outcome: interrupted`.
   *
   * @return the figures of summary.json.
   */
  RunSummary
  run_scene(const Parameters &parameters, std::ostream &out);

  /**
   * The same run written into @p directory, which the caller owns (a
   * sweep's run in the sweep's staging directory): created here, not
   * committed.
   */
  RunSummary
  run_scene_in(const Parameters  &parameters,
               const std::string &directory,
               std::ostream      &out);
} // namespace thinlayer

#endif
