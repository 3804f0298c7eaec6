#ifndef thinlayer_postprocess_monitors_h
#define thinlayer_postprocess_monitors_h

#include <deal.II/base/index_set.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/postprocess/displacement_measure.h>

#include <utility>

namespace thinlayer
{
  using namespace dealii;

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
             const AnalysisView<dim> &analysis,
             const std::string       &parameter_file);

    /// The load measure, times its scale.
    double
    load() const;

    /// The displacement measure, times its scale.
    DisplacementMeasure
    displacement() const;

    /// The displacement measure of the displacements @p modes (by mode,
    /// with their ghost values), times its scale: a collective call.
    DisplacementMeasure
    displacement_of(const ModeVectors &modes) const;

  private:
    /// The integral of the load's stress component over its material id,
    /// and the area of that material id: on many ranks, summed over the
    /// ranks' cells (every rank calls it).
    std::pair<double, double>
    stress_integral() const;

    /**
     * The resultant of the reactions (MonitorParameters::LoadComponent):
     * the residual f_int - f_ext at the DoFs of the load's boundary id,
     * after the residuals of eliminated centre nodes are handed to their
     * masters. In a Fourier analysis a mode's nodal forces are integrals
     * over the circle (int f T(n theta) r dtheta), so the whole body's
     * resultants are sums over the nodes of one mode: the axial force of
     * harmonic 0 (f_z), the force along theta = 0 of harmonic 1
     * (f_r - f_theta), its overturning moment (z (f_r - f_theta) - r f_z),
     * and the torque of the antisymmetric harmonic 0 (r f_theta). Each is
     * the work of the nodal forces on the rigid motion it belongs to,
     * which the element represents exactly.
     */
    double
    reaction() const;

    /// The sum over the load boundary's DoFs of component @p component of
    /// @p forces, each times the support point's coordinate @p weight_by
    /// (0: x or r, 1: y or z; -1: none), over all ranks (a collective
    /// call).
    double
    boundary_sum(const ModeVector  &forces,
                 const unsigned int component,
                 const int          weight_by = -1) const;

    const MonitorParameters &parameters;
    const AnalysisView<dim> &analysis;
    /// The cell holding the displacement point and the point in it, on
    /// the rank that evaluates it (the lowest that owns such a cell); an
    /// invalid cell on the others.
    std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
      point_cell;
    /// Per component, this rank's DoFs on the load's boundary id and
    /// their support points.
    std::vector<std::vector<std::pair<types::global_dof_index, Point<3>>>>
      reaction_dofs;
  };
} // namespace thinlayer

#endif
