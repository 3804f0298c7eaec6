#ifndef thinlayer_app_adaptive_run_h
#define thinlayer_app_adaptive_run_h

#include <thinlayer/output/run_summary.h>
#include <thinlayer/parameters/parameters.h>

#include <ostream>
#include <vector>

namespace thinlayer
{
  /**
   * Run a scene with refinement cycles (its Adaptivity section): the load
   * path on the mesh as given, then again and again on the mesh refined
   * where the last run's mechanism was (refinement_indicator(),
   * refine_mesh()), each cycle's run in cycle-N of the output directory.
   * The cycles stop at Adaptivity/Cycles, when the collapse load changes
   * by less than the stop tolerance, before a mesh beyond the DoF budget,
   * where a run found no plastic flow to refine toward, or on a signal.
   *
   * The output directory gets summary.json, the last cycle's summary with
   * every cycle under "adaptivity" (and the collapse load extrapolated from
   * the last three where they show a rate), and adaptivity.csv, one row per
   * cycle. It is written aside and put in place at the end, as a single
   * run's is.
   *
   * @return the summary written.
   */
  RunSummary
  run_adaptive(const Parameters &parameters, std::ostream &out);

  /**
   * The collapse load P_inf of P = P_inf + C N^(-rate), N the DoFs, through
   * the last three of @p cycles that have a collapse load: where the
   * differences between them have one sign and shrink (a rate between 0.05
   * and 5). Returns P_inf and the rate, or NaN twice where the cycles show
   * no such rate.
   */
  std::pair<double, double>
  extrapolate_collapse_load(const std::vector<CycleSummary> &cycles);
} // namespace thinlayer

#endif
