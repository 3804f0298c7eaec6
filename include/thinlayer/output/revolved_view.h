#ifndef thinlayer_output_revolved_view_h
#define thinlayer_output_revolved_view_h

#include <deal.II/base/data_out_base.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/postprocess/cell_fields.h>

#include <string>
#include <vector>

namespace thinlayer
{
  /**
   * The body of a Fourier analysis revolved about its axis, for ParaView:
   * each cell of the r-z mesh that this rank owns swept through @p slices
   * equal angles over the whole circle, as one VTU dataset (its text is
   * returned; on many ranks, each rank's piece) in Cartesian
   * coordinates (X, Y) = r (cos theta, sin theta), Z along the axis.
   *
   * The displacement is the sum over the harmonics at each slice's angles,
   * as a Cartesian vector at the vertices. The stresses (cylindrical
   * components rr, zz, tt, rz, rt, zt), the equivalent stress, the
   * equivalent plastic strain and the yield ratio exist at the stations
   * only, over [0, 180] degrees: a slice takes the cell averages of the
   * station nearest to its middle angle, mirrored into (180, 360) degrees
   * by the series' symmetry (for the symmetric series the shear stresses
   * with theta change sign there, for the antisymmetric one the others
   * do). A view, not an analysis: nothing is computed between stations.
   * The cell averages are @p fields, those of @p analysis, and the
   * displacements its @p modes (AnalysisView::displacements()), ghosts
   * imported: each rank has both on its own cells.
   */
  struct RevolvedView
  {
    /// One hexahedral patch per cell and slice, slice by slice.
    std::vector<DataOutBase::Patch<3, 3>> patches;
    /// The names of the patches' data rows; the first three are the
    /// displacement vector.
    std::vector<std::string> names;
  };

  RevolvedView
  revolved_view(const AnalysisView<2> &analysis,
                const CellFields      &fields,
                const ModeVectors     &modes,
                const unsigned int     slices);
} // namespace thinlayer

#endif
