#ifndef thinlayer_adaptivity_refinement_indicator_h
#define thinlayer_adaptivity_refinement_indicator_h

#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/parameters/adaptivity_section.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Where the mesh should be finer, per active cell of the whole mesh
   * (AnalysisView::get_whole_mesh(), by active cell index), the same on
   * every rank: at the last converged state, the plastic work
   * sigma : eps_p or the equivalent plastic strain sqrt(2/3 eps_p : eps_p)
   * of the continuum's points, integrated over the cell (area weights, times
   * r in Fourier scenes) and averaged over the stations. Integrated, not a
   * density: a cell's share of the mechanism's work is what its refinement
   * can change, and a large cell with moderate flow counts as much as a
   * small one with intense flow.
   *
   * Only accepted states count (the accepted stress and plastic strain), so
   * a failed attempt after the last converged step, whose points hold no
   * equilibrium, marks nothing. Negative values (a non-associated law can
   * give sigma : eps_p < 0 at a point) count as zero.
   */
  template <int dim>
  Vector<double>
  refinement_indicator(const AnalysisView<dim>              &analysis,
                       const AdaptivityParameters::Indicator indicator);
} // namespace thinlayer

#endif
