#ifndef thinlayer_postprocess_cell_fields_h
#define thinlayer_postprocess_cell_fields_h

#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/analysis_view.h>

#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Cell averages of the point fields: the stresses live at Gauss points
   * with their plastic history, not at nodes. At every station: the
   * stress components (the four that plane strain has; all six for
   * Fourier, where the shear stresses with theta come from the higher
   * harmonics), the equivalent stress, the equivalent plastic strain and
   * the yield ratio. The yield ratio is the cell's maximum, to show where
   * drift into illegal stress space is.
   *
   * On many ranks each rank has the averages of its own cells (zeros on
   * its ghost cells), the cells of the piece it writes.
   */
  struct CellFields
  {
    template <int dim>
    explicit CellFields(const AnalysisView<dim> &analysis);

    /// (i, j) of the stress components written: plane strain the first
    /// four (xx, yy, zz, xy), Fourier and 3D all six (rr, zz, tt, rz, rt,
    /// zt; xx, yy, zz, xy, xz, yz).
    static constexpr unsigned int components[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
    unsigned int n_components;
    /// Per station, per component.
    std::vector<std::vector<Vector<double>>> stress;
    std::vector<Vector<double>> equivalent, plastic_strain, yield_ratio;
    Vector<double>              material;
  };
} // namespace thinlayer

#endif
