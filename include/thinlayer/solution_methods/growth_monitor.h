#ifndef thinlayer_solution_methods_growth_monitor_h
#define thinlayer_solution_methods_growth_monitor_h

#include <deal.II/lac/vector.h>

#include <thinlayer/discretisation/mode_vectors.h>

#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Whether the displacement of a load step that runs to its iteration
   * limit is still growing: the evidence of a mechanism that an iterative
   * method gives when it creeps along one. The change of the step's
   * displacement increment since the first iteration is measured at half
   * the iterations and at the end: under a mechanism it grows linearly
   * (the body loads grow without bound), so the ratio is near 2; a step
   * that converges, however slowly, settles, and the ratio is nearer 1.
   */
  class GrowthMonitor
  {
  public:
    /// Keep the step increments after the first iteration.
    void
    start(const ModeVectors &step_increment);

    /// After iteration @p iteration of at most @p limit: at half the
    /// limit, measure the change.
    void
    iteration_done(const unsigned int iteration,
                   const unsigned int limit,
                   const ModeVectors &step_increment);

    /// The change at the end of the step against the change at half the
    /// limit; NaN if the step did not get that far.
    double
    growth_ratio(const ModeVectors &step_increment);

  private:
    /// max over the modes of max |du - du_first|.
    double
    change(const ModeVectors &step_increment);

    ModeVectors first;
    ModeVector  work;
    double      change_at_half = 0;
  };
} // namespace thinlayer

#endif
