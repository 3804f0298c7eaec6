#ifndef thinlayer_app_run_h
#define thinlayer_app_run_h

#include <deal.II/base/timer.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/output/run_summary.h>
#include <thinlayer/parameters/parameters.h>

#include <functional>
#include <ostream>
#include <string>

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

  /**
   * Run @p work into Output/Directory of @p parameters as one run of it: the
   * directory is written aside (ResultsDirectory) once @p work calls the
   * function it is given, which returns where to write (on every rank), and
   * put in place when @p work returns. A failed write names the directory;
   * an error leaves the previous run as it was.
   */
  RunSummary
  run_in_output_directory(
    const Parameters &parameters,
    const std::function<RunSummary(const std::function<std::string()> &)> &work,
    std::ostream                                                          &out);

  /// The run's first lines: the parameter file, its warnings, the mesh.
  void
  print_run_header(const Parameters &parameters, std::ostream &out);

  /**
   * The clocks of one run: its wall time and its sections (TimerOutput),
   * from before its mesh was made, and the memory the program held then.
   */
  struct RunClock
  {
    explicit RunClock(std::ostream &out);

    Timer       wall_clock;
    TimerOutput timer;
    double      program_memory_mb;
  };

  /**
   * The run of run_scene() on a mesh already made, @p scene (an adaptive
   * cycle's refined mesh), timed by @p clock, into the directory
   * @p open_directory gives once all input has been checked. @p read, where
   * given, is shown the analysis at the run's end, before it is gone (the
   * cycles read their refinement indicator off it).
   */
  template <int dim>
  RunSummary
  run_on_scene(const Parameters                   &parameters,
               const Scene<dim>                   &scene,
               RunClock                           &clock,
               const std::function<std::string()> &open_directory,
               std::ostream                       &out,
               const std::function<void(const AnalysisView<dim> &)> &read);
} // namespace thinlayer

#endif
