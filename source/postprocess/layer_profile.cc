#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_tools.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/postprocess/layer_profile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    using CellIterator = DoFHandler<2>::active_cell_iterator;

    /// A unit-cell point at abscissa @p along in direction @p direction and
    /// @p across in the other.
    Point<2>
    unit_point(const unsigned int direction,
               const double       along,
               const double       across)
    {
      Point<2> p;
      p[direction]     = along;
      p[1 - direction] = across;
      return p;
    }

    /// Lexicographic order of points, x before y, to a tolerance.
    bool
    lower_left(const Point<2> &a, const Point<2> &b, const double tolerance)
    {
      if (std::abs(a[0] - b[0]) > tolerance)
        return a[0] < b[0];
      return a[1] < b[1] - tolerance;
    }
  } // namespace


  const std::vector<std::string> LayerProfile<2>::cell_field_names = {
    "interface_slip",
    "interface_opening",
    "interface_shear_traction",
    "interface_normal_traction"};


  LayerProfile<2>::LayerProfile(const AnalysisView<2>   &analysis,
                                const types::material_id material_id,
                                const std::string       &parameter_file)
    : LayerReading<2>(material_id)
  {
    // The layer is chained on the whole mesh (its runs may cross ranks);
    // each rank then evaluates the samples of its own cells.
    const Triangulation<2> &tria = analysis.get_whole_mesh();
    const DoFHandler<2>     dof_handler(tria);
    const double            tolerance = 1e-9 * GridTools::diameter(tria);
    const std::string       entry     = "Layers/Material ids";
    const std::string       name = "material id " + std::to_string(material_id);

    // Each layer cell's long direction: the one in which its layer
    // neighbours lie (the chain runs through the short faces), or for a
    // cell alone its longer sides.
    std::map<CellIterator, unsigned int> long_direction;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->material_id() == material_id)
        {
          std::array<unsigned int, 2> neighbours = {{0, 0}};
          for (const unsigned int f : cell->face_indices())
            neighbours[f / 2] += in_layer_across(cell, f);
          unsigned int direction;
          if (neighbours[0] > 0 && neighbours[1] > 0)
            {
              std::ostringstream message;
              message << "expected a layer one cell thick, without "
                         "branches: the cell of "
                      << name << " at (" << cell->center()
                      << ") has cells of that material along two directions";
              throw InputError(parameter_file, entry, message.str());
            }
          else if (neighbours[0] + neighbours[1] > 0)
            direction = neighbours[0] > 0 ? 0 : 1;
          else
            direction = cell->face(2)->measure() + cell->face(3)->measure() >=
                            cell->face(0)->measure() + cell->face(1)->measure()
                          ? 0
                          : 1;
          long_direction[cell] = direction;
        }
    if (long_direction.empty())
      throw InputError(parameter_file,
                       entry,
                       "expected a material id of the mesh: no cell has " +
                         name);

    // Runs start at an end: a cell with a free short face, the one whose
    // free face is nearest the lower left first; closed loops last.
    std::vector<std::pair<Point<2>, std::pair<CellIterator, unsigned int>>>
      starts;
    for (const auto &[cell, direction] : long_direction)
      for (const unsigned int f : {2 * direction, 2 * direction + 1})
        if (!in_layer_across(cell, f))
          starts.push_back({cell->face(f)->center(), {cell, f}});
    std::sort(starts.begin(), starts.end(), [&](const auto &a, const auto &b) {
      return lower_left(a.first, b.first, tolerance);
    });
    for (const auto &[cell, direction] : long_direction)
      starts.push_back({cell->center(), {cell, 2 * direction}});

    std::set<CellIterator> visited;
    unsigned int           run = 0;
    for (const auto &start : starts)
      {
        CellIterator cell       = start.second.first;
        unsigned int entry_face = start.second.second;
        if (visited.count(cell) != 0)
          continue;
        double arc_length = 0;
        while (true)
          {
            visited.insert(cell);
            const unsigned int direction = long_direction.at(cell);
            arc_length                   = add_cell_samples(
              analysis, cell, direction, entry_face, run, arc_length);
            const unsigned int exit = entry_face ^ 1;
            if (!in_layer_across(cell, exit))
              break;
            const CellIterator next = cell->neighbor(exit);
            if (visited.count(next) != 0)
              break;
            entry_face = cell->neighbor_of_neighbor(exit);
            cell       = next;
            if (entry_face / 2 != long_direction.at(cell))
              {
                std::ostringstream message;
                message << "expected a layer one cell thick: the cell of "
                        << name << " at (" << cell->center()
                        << ") joins the layer through a long side";
                throw InputError(parameter_file, entry, message.str());
              }
          }
        ++run;
      }

    place_on_ranks(analysis);
  }


  double
  LayerProfile<2>::add_cell_samples(const AnalysisView<2> &analysis,
                                    const CellIterator    &cell,
                                    const unsigned int     long_direction,
                                    const unsigned int     entry_face,
                                    const unsigned int     run,
                                    const double           start)
  {
    const Mapping<2> &mapping = analysis.get_mapping();
    const auto        mid     = [&](const double along) {
      return mapping.transform_unit_to_real_cell(
        cell, unit_point(long_direction, along, 0.5));
    };
    // Along the layer from the entry face: +1 if it is the face at 0.
    const bool         forward = (entry_face % 2 == 0);
    const Point<2>     entry   = mid(forward ? 0. : 1.);
    const Tensor<1, 2> chord   = mid(forward ? 1. : 0.) - entry;
    // The layer's tangent at a point of its midline, along the run: on a
    // layer that follows a circle (attach_arcs()) it turns along the cell.
    const auto tangent_at = [&](const double along) {
      const double       h = 1e-6;
      const Tensor<1, 2> t = mid(along + h) - mid(along - h);
      return (forward ? 1. : -1.) * t / t.norm();
    };
    // Which unit face lies on the +n side.
    const Tensor<1, 2> chord_normal({-chord[1], chord[0]});
    const Tensor<1, 2> across =
      mapping.transform_unit_to_real_cell(cell,
                                          unit_point(long_direction, 0.5, 1.)) -
      mapping.transform_unit_to_real_cell(cell,
                                          unit_point(long_direction, 0.5, 0.));
    const double plus_face = (across * chord_normal > 0) ? 1. : 0.;

    const unsigned int n_1d = static_cast<unsigned int>(
      std::lround(std::sqrt(analysis.n_quadrature_points())));
    const QGauss<1>           gauss_1d(n_1d);
    const QGauss<2>           gauss_2d(n_1d);
    std::vector<unsigned int> order(n_1d);
    for (unsigned int q = 0; q < n_1d; ++q)
      order[q] = forward ? q : n_1d - 1 - q;
    // The cell as an element of the mid-line (TractionRecovery): its
    // samples' abscissae in the unit cell, and their weights (the rule's
    // times the mid-line's length element, times r in Fourier scenes).
    std::vector<unsigned int>          element_samples;
    std::vector<std::array<double, 2>> element_places;
    std::vector<double>                element_weights;
    for (const unsigned int q : order)
      {
        const double   along = gauss_1d.point(q)[0];
        const double   h     = 1e-6;
        const Point<2> at    = mid(along);
        element_samples.push_back(samples.size());
        element_places.push_back({{along, 0.}});
        element_weights.push_back(
          gauss_1d.weight(q) * (mid(along + h) - mid(along - h)).norm() /
          (2 * h) * analysis.get_kinematics().area_factor(at));

        const Tensor<1, 2> tangent = tangent_at(along);
        const Tensor<1, 2> normal({-tangent[1], tangent[0]});
        LayerSample<2>     sample;
        sample.cell       = cell;
        sample.t1         = Tensor<1, 3>({tangent[0], tangent[1], 0});
        sample.n          = Tensor<1, 3>({normal[0], normal[1], 0});
        sample.t2         = Tensor<1, 3>({0, 0, 1});
        sample.unit_plus  = unit_point(long_direction, along, plus_face);
        sample.unit_minus = unit_point(long_direction, along, 1 - plus_face);
        for (unsigned int q = 0; q < gauss_2d.size(); ++q)
          if (std::abs(gauss_2d.point(q)[long_direction] - along) < 1e-12)
            sample.thickness_points.push_back(q);
        samples.push_back(sample);
        const Point<2> position = mid(along);
        places.push_back({run,
                          start + (position - entry).norm(),
                          Point<3>(position[0], position[1], 0)});
      }
    recovery.add_element(element_samples,
                         element_places,
                         element_weights,
                         false,
                         [&](const double along, double) {
                           return TractionRecovery::node_key(
                             cell, unit_point(long_direction, along, 0.5));
                         });
    return start + chord.norm();
  }


  Profile
  LayerProfile<2>::profile(const AnalysisView<2> &analysis) const
  {
    Profile result;
    result.samples = places;
    for (unsigned int station = 0;
         station < analysis.get_kinematics().n_stations();
         ++station)
      result.stations.push_back(evaluate(analysis, station));
    return result;
  }


  std::vector<Vector<double>>
  LayerProfile<2>::cell_fields(const AnalysisView<2> &analysis,
                               const unsigned int     station) const
  {
    return layer_cell_averages(analysis,
                               samples,
                               evaluate(analysis, station),
                               {&InterfaceValues::slip,
                                &InterfaceValues::opening,
                                &InterfaceValues::shear_traction,
                                &InterfaceValues::normal_traction});
  }
} // namespace thinlayer
