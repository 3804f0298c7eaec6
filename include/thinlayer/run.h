#ifndef thinlayer_run_h
#define thinlayer_run_h

#include <thinlayer/parameters.h>
#include <thinlayer/run_summary.h>

#include <ostream>

namespace thinlayer
{
  /**
   * Run one scene from its parameters: build the mesh, set up the analysis,
   * apply the load programme step by step and write history.csv, VTU/PVD
   * and summary.json into the output directory. Screen output is one line
   * per load step. All input is checked (InputError) before the output
   * directory is touched.
   *
   * @return the figures of summary.json.
   */
  RunSummary
  run_scene(const Parameters &parameters, std::ostream &out);
} // namespace thinlayer

#endif
