#ifndef thinlayer_run_h
#define thinlayer_run_h

#include <thinlayer/output_writer.h>
#include <thinlayer/parameters.h>

#include <ostream>

namespace thinlayer
{
  /**
   * The figures of one run that summary.json and sweep.csv report.
   */
  struct RunSummary
  {
    bool         converged;
    double       last_converged_load;
    double       first_failed_load;
    double       reference_load;
    double       relative_error;
    unsigned int cells;
    unsigned int dofs;
    unsigned int equations;
    unsigned int load_steps;
    unsigned int total_iterations;
    /// The iterations of the steps up to the last converged one (those of
    /// a failed step depend on rounding).
    unsigned int converged_iterations;
    double       wall_seconds;
    /// Warnings about the model (e.g. too few stations); empty if none.
    std::string warnings;
  };

  /**
   * Run one scene from its parameters: build the mesh, set up the analysis,
   * apply the load programme step by step and write history.csv, VTU/PVD
   * and summary.json into the output directory. Screen output is one line
   * per load step. All input is checked (InputError) before the output
   * directory is touched.
   *
   * @return the main figures of summary.json.
   */
  RunSummary
  run_scene(const Parameters &parameters, std::ostream &out);
} // namespace thinlayer

#endif
