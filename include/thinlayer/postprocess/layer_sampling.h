#ifndef thinlayer_postprocess_layer_sampling_h
#define thinlayer_postprocess_layer_sampling_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/elements/interface_values.h>
#include <thinlayer/elements/traction_recovery.h>

#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Where a thin layer (a plane curve of quadrilaterals or a surface of
   * hexahedra, LayerProfile<dim>) is read at one sample: its cell as the
   * analysis holds it (where this rank's, @p own), the unit-cell points on
   * its two faces opposite the sample (+n, -n), the Gauss points across
   * the thickness there, and the frame: t1 and n in the layer's plane and
   * across it, t2 = t1 x n (z in plane strain, theta in Fourier scenes).
   */
  template <int dim>
  struct LayerSample
  {
    typename DoFHandler<dim>::active_cell_iterator cell;
    bool                                           own;
    Point<dim>                                     unit_plus;
    Point<dim>                                     unit_minus;
    std::vector<unsigned int>                      thickness_points;
    Tensor<1, 3>                                   t1;
    Tensor<1, 3>                                   n;
    Tensor<1, 3>                                   t2;
  };


  /**
   * The values of a layer at each of @p samples, at station @p station:
   * slip (along t1 and t2) and opening, the displacement on the + face
   * minus that on the - face; tractions, the stress averaged over the Gauss
   * points across the thickness, times n; the largest yield ratio there.
   * Samples of another rank's cells are left zero here and filled by
   * sum_over_ranks() (every rank calls it).
   */
  template <int dim>
  std::vector<InterfaceValues>
  evaluate_layer(const AnalysisView<dim>             &analysis,
                 const std::vector<LayerSample<dim>> &samples,
                 const unsigned int                   station);


  /**
   * What both LayerProfile classes share: the layer's material id and its
   * samples, read at a station.
   */
  template <int dim>
  class LayerReading
  {
  public:
    types::material_id
    get_material_id() const
    {
      return material_id;
    }

    unsigned int
    n_points() const
    {
      return samples.size();
    }

    /// The values at every sample, at station @p station. On many ranks
    /// every rank calls it, and receives the values of the samples in
    /// other ranks' cells from them.
    std::vector<InterfaceValues>
    evaluate(const AnalysisView<dim> &analysis,
             const unsigned int       station) const
    {
      return evaluate_layer(analysis, samples, station);
    }

    /// The tractions of @p profile, one of this layer's, recovered at the
    /// layer's nodes along its mid-line or mid-surface (TractionRecovery).
    void
    recover(Profile &profile) const
    {
      recovery.recover(profile);
    }

  protected:
    explicit LayerReading(const types::material_id material_id)
      : material_id(material_id)
    {}

    /// Whether the neighbour of @p cell across face @p f is in the layer.
    bool
    in_layer_across(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const unsigned int f) const
    {
      return !cell->at_boundary(f) && cell->neighbor(f)->is_active() &&
             cell->neighbor(f)->material_id() == material_id;
    }

    /// The samples, found on the whole mesh, moved to the cells as
    /// @p analysis holds them, where this rank's (@p own), so that each
    /// rank evaluates its own.
    void
    place_on_ranks(const AnalysisView<dim> &analysis);

    types::material_id            material_id;
    std::vector<LayerSample<dim>> samples;
    /// The samples of each cell as an element of the mid-line or
    /// mid-surface, its nodes named by the whole mesh's vertices.
    TractionRecovery recovery;
  };


  /**
   * The cell averages of @p fields (each a member of InterfaceValues) of
   * @p values at @p samples, over this rank's active cells: zero off the
   * layer and on other ranks' cells (for the VTU).
   */
  template <int dim>
  std::vector<Vector<double>>
  layer_cell_averages(const AnalysisView<dim>                      &analysis,
                      const std::vector<LayerSample<dim>>          &samples,
                      const std::vector<InterfaceValues>           &values,
                      const std::vector<double InterfaceValues::*> &fields);
} // namespace thinlayer

#endif
