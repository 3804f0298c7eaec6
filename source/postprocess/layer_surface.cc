#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_tools.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/postprocess/layer_profile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    using CellIterator = DoFHandler<3>::active_cell_iterator;

    /// The unit-cell point with coordinate @p a and @p b in the two
    /// directions other than @p thickness (in increasing order) and
    /// @p across in it.
    Point<3>
    unit_point(const unsigned int thickness,
               const double       a,
               const double       b,
               const double       across)
    {
      Point<3>           p;
      const unsigned int first  = thickness == 0 ? 1 : 0;
      const unsigned int second = thickness == 2 ? 1 : 2;
      p[first]                  = a;
      p[second]                 = b;
      p[thickness]              = across;
      return p;
    }
  } // namespace


  const std::vector<std::string> LayerProfile<3>::cell_field_names = {
    "interface_slip_1",
    "interface_slip_2",
    "interface_opening",
    "interface_shear_traction_1",
    "interface_shear_traction_2",
    "interface_normal_traction"};


  LayerProfile<3>::LayerProfile(const AnalysisView<3>   &analysis,
                                const types::material_id material_id,
                                const std::string       &parameter_file)
    : LayerReading<3>(material_id)
  {
    // The layer is found on the whole mesh, in the order of its cells;
    // each rank then evaluates the samples of its own cells.
    const Triangulation<3> &tria = analysis.get_whole_mesh();
    const DoFHandler<3>     dof_handler(tria);
    const std::string       entry = "Layers/Material ids";
    const std::string       name = "material id " + std::to_string(material_id);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == material_id)
        {
          // The thickness direction: no layer neighbour across it, the
          // shortest such.
          int    thickness = -1;
          double shortest  = std::numeric_limits<double>::max();
          for (unsigned int d = 0; d < 3; ++d)
            if (!in_layer_across(cell, 2 * d) &&
                !in_layer_across(cell, 2 * d + 1))
              {
                const double length = (cell->face(2 * d + 1)->center() -
                                       cell->face(2 * d)->center())
                                        .norm();
                if (length < shortest)
                  {
                    shortest  = length;
                    thickness = d;
                  }
              }
          if (thickness < 0)
            {
              std::ostringstream message;
              message << "expected a layer one cell thick: the cell of " << name
                      << " at (" << cell->center()
                      << ") has cells of that material on every side";
              throw InputError(parameter_file, entry, message.str());
            }
          add_cell_samples(analysis, cell, thickness);
        }
    if (samples.empty())
      throw InputError(parameter_file,
                       entry,
                       "expected a material id of the mesh: no cell has " +
                         name);

    place_on_ranks(analysis);
  }


  void
  LayerProfile<3>::add_cell_samples(const AnalysisView<3> &analysis,
                                    const CellIterator    &cell,
                                    const unsigned int     thickness)
  {
    const Mapping<3> &mapping = analysis.get_mapping();
    const auto at = [&](const double a, const double b, const double across) {
      return mapping.transform_unit_to_real_cell(
        cell, unit_point(thickness, a, b, across));
    };
    // The mid-surface's normal at a point, from its two tangents there: on
    // a layer that follows a cylinder (attach_arcs()) it turns across the
    // cell.
    const auto normal_at = [&](const double a, const double b) {
      const double       h   = 1e-6;
      const Tensor<1, 3> t_a = at(a + h, b, 0.5) - at(a - h, b, 0.5);
      const Tensor<1, 3> t_b = at(a, b + h, 0.5) - at(a, b - h, 0.5);
      const Tensor<1, 3> n   = cross_product_3d(t_a, t_b);
      return upward(n / n.norm());
    };

    const unsigned int n_1d = static_cast<unsigned int>(
      std::lround(std::cbrt(analysis.n_quadrature_points())));
    const QGauss<1> gauss_1d(n_1d);
    const QGauss<3> gauss_3d(n_1d);
    // The cell as an element of the mid-surface (TractionRecovery): its
    // samples' places and weights (the rule's times the area element).
    std::vector<unsigned int>          element_samples;
    std::vector<std::array<double, 2>> element_places;
    std::vector<double>                element_weights;
    const double                       h = 1e-6;
    for (unsigned int i = 0; i < n_1d; ++i)
      for (unsigned int j = 0; j < n_1d; ++j)
        {
          const double a = gauss_1d.point(i)[0];
          const double b = gauss_1d.point(j)[0];
          element_samples.push_back(samples.size());
          element_places.push_back({{a, b}});
          element_weights.push_back(
            gauss_1d.weight(i) * gauss_1d.weight(j) *
            cross_product_3d(at(a + h, b, 0.5) - at(a - h, b, 0.5),
                             at(a, b + h, 0.5) - at(a, b - h, 0.5))
              .norm() /
            (4 * h * h));
          const Tensor<1, 3> normal  = normal_at(a, b);
          const Tensor<1, 3> tangent = first_tangent(normal);
          // Which unit face lies on the +n side.
          const double plus_face =
            (at(a, b, 1) - at(a, b, 0)) * normal > 0 ? 1. : 0.;
          LayerSample<3> sample;
          sample.cell             = cell;
          sample.t1               = tangent;
          sample.n                = normal;
          sample.t2               = cross_product_3d(tangent, normal);
          sample.unit_plus        = unit_point(thickness, a, b, plus_face);
          sample.unit_minus       = unit_point(thickness, a, b, 1 - plus_face);
          const Point<3> in_plane = unit_point(thickness, a, b, 0);
          for (unsigned int q = 0; q < gauss_3d.size(); ++q)
            {
              Point<3> x   = gauss_3d.point(q);
              x[thickness] = 0;
              if (x.distance(in_plane) < 1e-12)
                sample.thickness_points.push_back(q);
            }
          const double a0 = double(i) / n_1d, a1 = double(i + 1) / n_1d;
          const double b0 = double(j) / n_1d, b1 = double(j + 1) / n_1d;
          places.push_back({at(a, b, 0.5),
                            tangent,
                            normal,
                            {{at(a0, b0, 0.5),
                              at(a1, b0, 0.5),
                              at(a1, b1, 0.5),
                              at(a0, b1, 0.5)}}});
          samples.push_back(sample);
        }
    recovery.add_element(element_samples,
                         element_places,
                         element_weights,
                         true,
                         [&](const double a, const double b) {
                           return TractionRecovery::node_key(
                             cell, unit_point(thickness, a, b, 0.5));
                         });
  }


  Profile
  LayerProfile<3>::profile(const AnalysisView<3> &analysis) const
  {
    Profile result;
    result.surface_samples = places;
    result.stations.push_back(evaluate(analysis, 0));
    return result;
  }


  std::vector<Vector<double>>
  LayerProfile<3>::cell_fields(const AnalysisView<3> &analysis,
                               const unsigned int     station) const
  {
    return layer_cell_averages(analysis,
                               samples,
                               evaluate(analysis, station),
                               {&InterfaceValues::slip,
                                &InterfaceValues::slip_out_of_plane,
                                &InterfaceValues::opening,
                                &InterfaceValues::shear_traction,
                                &InterfaceValues::shear_traction_out_of_plane,
                                &InterfaceValues::normal_traction});
  }
} // namespace thinlayer
