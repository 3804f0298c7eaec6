#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <thinlayer/elements/interface_geometry.h>

#include <limits>

// Where the integration points of an interface element lie: along a curve's
// straight side, or over a hexahedron's face.
namespace thinlayer
{
  namespace
  {
    /// The points along a straight side of a curve: on its chord, one
    /// frame for the side.
    std::vector<InterfacePointPlace<2>>
    points_on_chord(const FacingSides<2> &pair,
                    const Quadrature<1>  &rule,
                    const Kinematics     &kinematics)
    {
      std::vector<InterfacePointPlace<2>> places;
      const Tensor<1, 2>                  chord   = pair.exit - pair.entry;
      const double                        length  = chord.norm();
      const Tensor<1, 2>                  tangent = chord / length;
      const Tensor<2, 3>                  frame({{tangent[0], tangent[1], 0.},
                                                 {-tangent[1], tangent[0], 0.},
                                                 {0., 0., 1.}});
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          InterfacePointPlace<2> place;
          place.position = pair.entry + rule.point(q)[0] * chord;
          place.frame    = frame;
          place.weight =
            rule.weight(q) * length * kinematics.area_factor(place.position);
          place.arc_length   = pair.arc_length + rule.point(q)[0] * length;
          place.unit_plus[0] = std::numeric_limits<double>::quiet_NaN();
          place.rule_place   = {{rule.point(q)[0], 0.}};
          places.push_back(place);
        }
      return places;
    }


    /**
     * The points along the plus cell's side of a pair on a curve, through
     * the mapping: on a side that follows a circle (attach_arcs()) they lie
     * on the circle, and each point's frame turns with the side's tangent
     * there. A straight side keeps points_on_chord(), the same points to
     * round-off: near a collapse, round-off decides whether a failed
     * step's iterations show the mechanism.
     */
    std::vector<InterfacePointPlace<2>>
    points_on_side(const FacingSides<2> &pair,
                   const Quadrature<1>  &rule,
                   const Mapping<2>     &mapping,
                   const Kinematics     &kinematics)
    {
      if (pair.plus_cell->face(pair.plus_face)->manifold_id() ==
          numbers::flat_manifold_id)
        return points_on_chord(pair, rule, kinematics);

      // The plus cell's face f: unit coordinate d = f / 2 fixed at f % 2,
      // the other one running along the side.
      const unsigned int f      = pair.plus_face;
      const unsigned int d      = f / 2;
      const unsigned int along  = 1 - d;
      const double       across = f % 2;
      const auto         unit   = [&](const double s) {
        Point<2> p;
        p[along] = s;
        p[d]     = across;
        return p;
      };
      const typename Triangulation<2>::cell_iterator cell(pair.plus_cell);
      // Whether the side runs from the pair's entry at unit 0.
      const Point<2> at_zero =
        mapping.transform_unit_to_real_cell(cell, unit(0));
      const bool forward =
        at_zero.distance(pair.entry) <= at_zero.distance(pair.exit);

      std::vector<Point<2>> units;
      for (unsigned int q = 0; q < rule.size(); ++q)
        units.push_back(
          unit(forward ? rule.point(q)[0] : 1 - rule.point(q)[0]));
      const FE_Q<2> linear(1);
      FEValues<2>   values(mapping,
                         linear,
                         Quadrature<2>(units),
                         update_quadrature_points | update_jacobians);
      values.reinit(cell);

      const double chord = (pair.exit - pair.entry).norm();
      std::vector<InterfacePointPlace<2>> places;
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          const DerivativeForm<1, 2, 2> &J = values.jacobian(q);
          Tensor<1, 2>                   tangent({J[0][along], J[1][along]});
          const double                   stretch = tangent.norm();
          tangent /= forward ? stretch : -stretch;
          InterfacePointPlace<2> place;
          place.position = values.quadrature_point(q);
          place.frame    = Tensor<2, 3>({{tangent[0], tangent[1], 0.},
                                         {-tangent[1], tangent[0], 0.},
                                         {0., 0., 1.}});
          place.weight =
            rule.weight(q) * stretch * kinematics.area_factor(place.position);
          place.arc_length = pair.arc_length + rule.point(q)[0] * chord;
          place.unit_plus  = units[q];
          place.rule_place = {{rule.point(q)[0], 0.}};
          places.push_back(place);
        }
      return places;
    }


    /// The points over the plus cell's face of a pair on a surface.
    std::vector<InterfacePointPlace<3>>
    points_on_face(const FacingSides<3> &pair,
                   const Quadrature<1>  &rule,
                   const Mapping<3>     &mapping)
    {
      std::vector<InterfacePointPlace<3>> places;
      // The plus cell's face f: unit coordinate d = f / 2 fixed at f % 2,
      // the points a tensor product over the other two; each point's
      // patch spans the rule's cumulative weights around it.
      const unsigned int f      = pair.plus_face;
      const unsigned int d      = f / 2;
      const double       across = f % 2;
      const unsigned int first  = d == 0 ? 1 : 0;
      const unsigned int second = d == 2 ? 1 : 2;
      const auto         unit   = [&](const double a, const double b) {
        Point<3> p;
        p[first]  = a;
        p[second] = b;
        p[d]      = across;
        return p;
      };
      std::vector<double> bounds = {0.};
      for (unsigned int k = 0; k < rule.size(); ++k)
        bounds.push_back(bounds.back() + rule.weight(k));

      std::vector<Point<3>> units;
      for (unsigned int j = 0; j < rule.size(); ++j)
        for (unsigned int i = 0; i < rule.size(); ++i)
          units.push_back(unit(rule.point(i)[0], rule.point(j)[0]));
      const FE_Q<3>                                  linear(1);
      FEValues<3>                                    values(mapping,
                         linear,
                         Quadrature<3>(units),
                         update_quadrature_points | update_jacobians);
      const typename Triangulation<3>::cell_iterator cell(pair.plus_cell);
      values.reinit(cell);
      for (unsigned int j = 0, q = 0; j < rule.size(); ++j)
        for (unsigned int i = 0; i < rule.size(); ++i, ++q)
          {
            const DerivativeForm<1, 3, 3> &J = values.jacobian(q);
            Tensor<1, 3>                   e_a, e_b, e_d;
            for (unsigned int c = 0; c < 3; ++c)
              {
                e_a[c] = J[c][first];
                e_b[c] = J[c][second];
                e_d[c] = J[c][d];
              }
            const Tensor<1, 3> area = cross_product_3d(e_a, e_b);
            // The normal points away from the plus cell, whose inside
            // lies along +e_d from the face at unit 0, along -e_d at 1.
            Tensor<1, 3> n = area / area.norm();
            if ((n * e_d) * (across == 0 ? 1. : -1.) < 0)
              n = -n;
            const Tensor<1, 3>     t1 = first_tangent(n);
            const Tensor<1, 3>     t2 = cross_product_3d(t1, n);
            InterfacePointPlace<3> place;
            place.position   = values.quadrature_point(q);
            place.frame      = Tensor<2, 3>({{t1[0], t1[1], t1[2]},
                                             {n[0], n[1], n[2]},
                                             {t2[0], t2[1], t2[2]}});
            place.weight     = rule.weight(i) * rule.weight(j) * area.norm();
            place.arc_length = 0;
            place.unit_plus  = units[q];
            place.rule_place = {{rule.point(i)[0], rule.point(j)[0]}};
            const double a0 = bounds[i], a1 = bounds[i + 1];
            const double b0 = bounds[j], b1 = bounds[j + 1];
            place.patch = {
              {mapping.transform_unit_to_real_cell(cell, unit(a0, b0)),
               mapping.transform_unit_to_real_cell(cell, unit(a1, b0)),
               mapping.transform_unit_to_real_cell(cell, unit(a1, b1)),
               mapping.transform_unit_to_real_cell(cell, unit(a0, b1))}};
            places.push_back(place);
          }
      return places;
    }
  } // namespace


  template <int dim>
  std::vector<InterfacePointPlace<dim>>
  interface_point_places(const FacingSides<dim>           &pair,
                         const InterfaceElementParameters &curve,
                         const Mapping<dim>               &mapping,
                         const Kinematics                 &kinematics)
  {
    const Quadrature<1> rule =
      curve.integration == InterfaceElementParameters::Integration::lobatto
        ? Quadrature<1>(QGaussLobatto<1>(3))
        : Quadrature<1>(QGauss<1>(curve.points));
    if constexpr (dim == 2)
      return points_on_side(pair, rule, mapping, kinematics);
    else
      {
        (void)kinematics;
        return points_on_face(pair, rule, mapping);
      }
  }


  template std::vector<InterfacePointPlace<2>>
  interface_point_places(const FacingSides<2> &,
                         const InterfaceElementParameters &,
                         const Mapping<2> &,
                         const Kinematics &);
  template std::vector<InterfacePointPlace<3>>
  interface_point_places(const FacingSides<3> &,
                         const InterfaceElementParameters &,
                         const Mapping<3> &,
                         const Kinematics &);
} // namespace thinlayer
