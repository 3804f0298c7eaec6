#ifndef thinlayer_elements_interface_geometry_h
#define thinlayer_elements_interface_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/mapping.h>

#include <thinlayer/discretisation/kinematics.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/parameters/interface_sections.h>

#include <array>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /// Where an integration point of an interface element lies, before its
  /// jump operator is known.
  template <int dim>
  struct InterfacePointPlace
  {
    Point<dim> position;
    /// The local axes (s, n, t) as rows, in the displacement's components:
    /// (x, y, theta or z) on a curve, (x, y, z) on a surface.
    Tensor<2, 3> frame;
    /// Quadrature weight times side length or face area, times r for
    /// Fourier.
    double weight;
    /// Along a curve: the arc length of its run.
    double arc_length;
    /// On a surface: the patch of the face the point stands for (its
    /// weight's share), for the profile's VTU.
    std::array<Point<3>, 4> patch;
    /// The point in the plus cell's unit cell (NaN on a straight side of a
    /// curve, where it is found from @p position).
    Point<dim> unit_plus;
    /// The point of the rule: on a curve its abscissa from the side's
    /// entry, in [0, 1]; on a face its two coordinates, along the plus
    /// cell's unit axes other than the face's normal one, in increasing
    /// order.
    std::array<double, 2> rule_place;
  };


  /**
   * The integration points of an interface element, the facing sides
   * @p pair, by the rule of @p curve (Gauss or Lobatto, per direction of a
   * face):
   * - on a curve, along the side's chord where it is straight, the frame
   *   the chord's tangent and its quarter turn anticlockwise; where the
   *   side follows a circle (attach_arcs()), along the plus cell's side as
   *   @p mapping maps it, the frame turning with the side's tangent, the
   *   weight its length element;
   * - on a surface, over the plus cell's face as @p mapping maps it: at each
   *   point the normal n pointing away from the plus cell (upward by
   *   pair_facing_sides()), t1 = first_tangent(n), t2 = t1 x n, the weight
   *   the face's area element, and a patch spanning the rule's cumulative
   *   weights around the point.
   */
  template <int dim>
  std::vector<InterfacePointPlace<dim>>
  interface_point_places(const FacingSides<dim>           &pair,
                         const InterfaceElementParameters &curve,
                         const Mapping<dim>               &mapping,
                         const Kinematics                 &kinematics);
} // namespace thinlayer

#endif
