#ifndef thinlayer_monitors_h
#define thinlayer_monitors_h

#include <deal.II/base/index_set.h>

#include <thinlayer/analysis.h>
#include <thinlayer/parameters.h>

#include <utility>

namespace thinlayer
{
  using namespace dealii;

  /**
   * A displacement component over a boundary: length-weighted mean, and the
   * extremes over its nodes (their spread shows how uniform it is).
   */
  struct DisplacementMeasure
  {
    double mean;
    double min;
    double max;
  };

  /**
   * What the "load" and "displacement" columns of history.csv measure on an
   * analysis, as the Monitors section asks: the load factor, a sum of
   * reactions or a stress averaged over a material id, each times a scale;
   * and a displacement component averaged over a boundary id, or at a
   * point. Monitors read the body; they never change it.
   */
  template <int dim>
  class Monitors
  {
  public:
    /**
     * Monitors of @p analysis, which must be set up. A displacement point
     * outside the mesh is an InputError naming the entry of
     * @p parameter_file.
     */
    Monitors(const MonitorParameters &parameters,
             const Analysis<dim>     &analysis,
             const std::string       &parameter_file);

    /// The load measure, times its scale.
    double
    load() const;

    /// The displacement measure, times its scale.
    DisplacementMeasure
    displacement() const;

  private:
    /// The integral of the load's stress component over its material id,
    /// and the area of that material id.
    std::pair<double, double>
    stress_integral() const;

    /**
     * The reactions: the residual f_int - f_ext at the supported DoFs of
     * the load's boundary id, after the residuals of eliminated centre
     * nodes are handed to their masters.
     */
    double
    reaction() const;

    const MonitorParameters &parameters;
    const Analysis<dim>     &analysis;
    /// The load component's DoFs on the load's boundary id.
    IndexSet reaction_dofs;
  };
} // namespace thinlayer

#endif
