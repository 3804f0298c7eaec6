#ifndef thinlayer_elements_traction_recovery_h
#define thinlayer_elements_traction_recovery_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/point.h>

#include <thinlayer/elements/interface_values.h>

#include <algorithm>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The tractions of an interface recovered at its nodes, work-conjugate:
   * the nodal forces f_i = sum_g N_i(xi_g) t_g w_g of the interface's
   * elements, summed over the elements that share node i, divided by the
   * node's tributary length or area m_i = sum_g N_i(xi_g) w_g; the
   * recovered field is sum_i N_i t_i, written where the raw values were.
   *
   * Why: once the soil flows, the tractions at the Gauss points of stiff
   * interface elements oscillate from point to point (Schellekens and de
   * Borst), and a thin layer of Q8 2x2 cells carries a mode linear within
   * each cell, antisymmetric about its centre, whose amplitude can far
   * exceed the signal. The nodal forces of neighbouring elements at a
   * shared node cancel those modes, so the recovered field is smooth where
   * the point values are not. The recovery keeps the resultant: the sum of
   * the f_i is the sum of the t_g w_g, and the field's integral by the same
   * rule is the same sum.
   *
   * The nodes are the elements' corners, N_i linear along a side and
   * bilinear over a face (a single point per direction: the element's
   * mean). The quadratic side's midside node would keep the part of the
   * traction quadratic within each element, and that is where a stiff
   * penalty puts the soil's within-cell stress variation near a
   * singularity: under a smooth rigid footing it leaves ripples of several
   * percent one to three cells from the edge, which the corner nodes
   * average away. Corner weights are also all positive, unlike a
   * serendipity face's.
   */
  class TractionRecovery
  {
  public:
    /**
     * The name of a node shared by the elements of an interface: the
     * sorted global indices of the vertices of @p cell that span the
     * mesh entity on which the unit point @p unit lies (a vertex, the two
     * ends of an edge, the four corners of a face, a cell's all), where
     * each coordinate of @p unit is 0, 1/2 or 1. Cells that share the
     * entity give the same name on every rank.
     */
    template <int dim, typename CellIterator>
    static std::vector<unsigned int>
    node_key(const CellIterator &cell, const Point<dim> &unit)
    {
      std::vector<unsigned int> key;
      for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
        {
          bool on = true;
          for (unsigned int d = 0; d < dim; ++d)
            if (unit[d] != 0.5 && unit[d] != double((v >> d) & 1))
              on = false;
          if (on)
            key.push_back(cell->vertex_index(v));
        }
      std::sort(key.begin(), key.end());
      return key;
    }

    /**
     * Add an element: its samples @p samples (indices into the profile)
     * at @p places, each a point of the element's unit interval (on a
     * curve, @p surface false: the first coordinate) or square (@p surface
     * true), a tensor product of n points per direction, with their
     * weights @p weights (rule weight times length or area element,
     * times r in Fourier scenes). @p key names the node at a point of
     * the unit interval or square (node_key()).
     */
    void
    add_element(
      const std::vector<unsigned int>                                &samples,
      const std::vector<std::array<double, 2>>                       &places,
      const std::vector<double>                                      &weights,
      const bool                                                      surface,
      const std::function<std::vector<unsigned int>(double, double)> &key);

    /**
     * Replace the shear, normal and out-of-plane shear tractions of
     * @p values (one per sample, every station's in turn) by the recovered
     * field at each sample. Samples of no element keep theirs.
     */
    void
    recover(std::vector<InterfaceValues> &values) const;

    /// The same at every station of @p profile.
    void
    recover(Profile &profile) const
    {
      for (std::vector<InterfaceValues> &values : profile.stations)
        recover(values);
    }

    /// One more than the largest sample of the elements added.
    unsigned int
    n_samples() const
    {
      return weights.size();
    }

  private:
    std::map<std::vector<unsigned int>, unsigned int> nodes;
    /// Per sample: its nodes and their shape values there.
    std::vector<std::vector<std::pair<unsigned int, double>>> shapes;
    std::vector<double>                                       weights;
  };
} // namespace thinlayer

#endif
