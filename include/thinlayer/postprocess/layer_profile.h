#ifndef thinlayer_postprocess_layer_profile_h
#define thinlayer_postprocess_layer_profile_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/analysis/analysis_view.h>
#include <thinlayer/elements/interface_values.h>
#include <thinlayer/postprocess/layer_sampling.h>

#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The profile of a thin-layer interface of a @p dim dimensional mesh.
   * The 2D one (a layer of cells chained into runs) is below; in 3D the
   * layer is a surface of hexahedra.
   */
  template <int dim>
  class LayerProfile;


  /**
   * The profile of a thin-layer interface: the cells of one material id,
   * one cell thick, chained through their short sides into one or more
   * runs, sampled at the Gauss abscissae along the layer (where the
   * stresses live). At each sample:
   *
   * - position and arc length along the layer's mid-line (each run from
   *   the end nearest the lower left, x before y);
   * - slip and opening: the displacement on the layer's two long faces at
   *   the sample's abscissa, differenced: the facing points that a
   *   zero-thickness element would pair (so a layer under a uniform strain
   *   eps shows eps d, d the offset between those points, t n where the
   *   short sides are normal to the layer);
   * - tractions: the stress averaged over the Gauss points across the
   *   thickness, on the layer's plane; recover() recovers them at the
   *   layer's nodes along its mid-line (TractionRecovery: each cell an
   *   element of the mid-line, its nodes on the short sides), evaluated at
   *   the samples.
   *
   * The tangent of each cell is its mid-line's chord, so cells are taken
   * as straight, as gmsh makes them. In Fourier scenes the profile is
   * taken at every station.
   */
  template <>
  class LayerProfile<2> : public LayerReading<2>
  {
  public:
    /**
     * The layer of material id @p material_id in @p analysis. Throws
     * InputError (naming @p parameter_file and the entry
     * Layers/Material ids) if no cell has that id or the layer is more
     * than one cell thick.
     */
    LayerProfile(const AnalysisView<2>   &analysis,
                 const types::material_id material_id,
                 const std::string       &parameter_file);

    /// The values at every sample and station, those of the Gauss points
    /// (every rank calls it); recover() recovers its tractions.
    Profile
    profile(const AnalysisView<2> &analysis) const;

    /**
     * Cell averages of slip, opening, shear and normal traction at station
     * @p station, over this rank's active cells (zero off the layer and on
     * other ranks' cells), for the VTU (every rank calls it).
     */
    std::vector<Vector<double>>
    cell_fields(const AnalysisView<2> &analysis,
                const unsigned int     station) const;

    /// The names of cell_fields()' vectors.
    static const std::vector<std::string> cell_field_names;

  private:
    /// The samples of one cell, entered through its short face
    /// @p entry_face, with arc length @p start at that face; returns the
    /// arc length at the far face.
    double
    add_cell_samples(const AnalysisView<2>                     &analysis,
                     const DoFHandler<2>::active_cell_iterator &cell,
                     const unsigned int                         long_direction,
                     const unsigned int                         entry_face,
                     const unsigned int                         run,
                     const double                               start);

    /// Where each sample lies along the layer.
    std::vector<ProfileSample> places;
  };


  /**
   * The profile of a thin layer in a 3D body: the hexahedra of one material
   * id, one cell thick, form a surface, sampled at the Gauss points of
   * each cell's mid-surface (where the stresses live). A cell's thickness
   * direction is the one in which no cell of the layer adjoins it (the
   * shortest such where there are several: a cell at the layer's edge or
   * alone). At each sample:
   *
   * - position, and the frame: the normal n of the mid-surface, pointing
   *   up (n_y > 0; where the layer is vertical, along +x, then +z), the
   *   first tangent t1 the x axis projected onto the surface (the z axis
   *   where the surface is normal to x), t2 = t1 x n: on a horizontal
   *   layer t1, n, t2 are x, y, z;
   * - slip (along t1 and t2) and opening: the displacement on the two
   *   faces of the cell at the sample, differenced (the + face minus the -
   *   face);
   * - tractions: the stress averaged over the Gauss points across the
   *   thickness, sigma n along t1, t2 and n; recover() recovers them at
   *   the corners of the cells' mid-surfaces (TractionRecovery), evaluated
   *   at the samples.
   *
   * The output is a surface: each sample stands for the patch of its
   * cell's mid-surface around it.
   */
  template <>
  class LayerProfile<3> : public LayerReading<3>
  {
  public:
    /// As LayerProfile<2>'s.
    LayerProfile(const AnalysisView<3>   &analysis,
                 const types::material_id material_id,
                 const std::string       &parameter_file);

    /// As LayerProfile<2>'s.
    Profile
    profile(const AnalysisView<3> &analysis) const;

    std::vector<Vector<double>>
    cell_fields(const AnalysisView<3> &analysis,
                const unsigned int     station) const;

    static const std::vector<std::string> cell_field_names;

  private:
    /// The samples of one cell whose thickness direction is
    /// @p thickness.
    void
    add_cell_samples(const AnalysisView<3>                     &analysis,
                     const DoFHandler<3>::active_cell_iterator &cell,
                     const unsigned int                         thickness);

    std::vector<SurfaceSample> places;
  };
} // namespace thinlayer

#endif
