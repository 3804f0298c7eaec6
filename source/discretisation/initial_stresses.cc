#include <thinlayer/base/input_error.h>
#include <thinlayer/base/text_format.h>
#include <thinlayer/discretisation/body_loads.h>
#include <thinlayer/discretisation/initial_stresses.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  KZeroStresses::KZeroStresses(const Triangulation<2> &mesh,
                               const Parameters       &parameters)
    : parameters(parameters)
    , level(thinlayer::ground_level(mesh))
  {
    // Every boundary face that faces upward is the ground surface: it must
    // be horizontal and at the top level. The sides of interface elements
    // (the mesh is split along them) are inside the body.
    double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        for (const auto f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary() ||
                parameters.interface_elements.count(
                  cell->face(f)->boundary_id()) > 0)
              continue;
            const Tensor<1, 2> n = outward_normal<2>(cell, f);
            if (n[1] <= 1e-9)
              continue;
            const Point<2> a       = cell->face(f)->vertex(0),
                           b       = cell->face(f)->vertex(1);
            const double tolerance = 1e-6 * cell->diameter();
            if (std::abs(a[1] - level) > tolerance ||
                std::abs(b[1] - level) > tolerance)
              throw InputError(
                parameters.parameter_file,
                "Initial state/Procedure",
                "the K0 procedure needs a level ground surface, but the "
                "boundary face from (" +
                  text_format::printf("%g", a[0]) + ", " +
                  text_format::printf("%g", a[1]) + ") to (" +
                  text_format::printf("%g", b[0]) + ", " +
                  text_format::printf("%g", b[1]) +
                  ") faces upward below the top level y = " +
                  text_format::printf("%g", level) +
                  " (a slope, a step or a structure above the ground); "
                  "expected 'gravity loading' for such a body");
          }
        Cell c;
        for (unsigned int v = 0; v < 4; ++v)
          c.vertices[v] = cell->vertex(v);
        c.x_min             = std::min({c.vertices[0][0],
                                        c.vertices[1][0],
                                        c.vertices[2][0],
                                        c.vertices[3][0]});
        c.x_max             = std::max({c.vertices[0][0],
                                        c.vertices[1][0],
                                        c.vertices[2][0],
                                        c.vertices[3][0]});
        const auto material = parameters.materials.find(cell->material_id());
        c.unit_weight       = material == parameters.materials.end()
                                ? 0
                                : material->second.unit_weight;
        x_min               = std::min(x_min, c.x_min);
        x_max               = std::max(x_max, c.x_max);
        cells.push_back(c);
      }

    const unsigned int n_bins = std::max<unsigned int>(
      1, static_cast<unsigned int>(std::sqrt(double(cells.size()))));
    x_start   = x_min;
    bin_width = (x_max - x_min) / n_bins;
    bins.resize(n_bins);
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        const auto first = static_cast<unsigned int>(
          std::clamp((cells[i].x_min - x_start) / bin_width, 0., n_bins - 1.));
        const auto last = static_cast<unsigned int>(
          std::clamp((cells[i].x_max - x_start) / bin_width, 0., n_bins - 1.));
        for (unsigned int b = first; b <= last; ++b)
          bins[b].push_back(i);
      }
  }


  double
  KZeroStresses::ground_level() const
  {
    return level;
  }


  const std::vector<unsigned int> &
  KZeroStresses::bin(const double x) const
  {
    const double b =
      std::clamp((x - x_start) / bin_width, 0., bins.size() - 1.);
    return bins[static_cast<unsigned int>(b)];
  }


  double
  KZeroStresses::overburden(const Point<2> &x) const
  {
    double weight = 0;
    for (const unsigned int i : bin(x[0]))
      {
        const Cell &c = cells[i];
        // Half-open: a vertical edge at x belongs to the cell on its right.
        if (c.unit_weight == 0 || !(c.x_min <= x[0] && x[0] < c.x_max))
          continue;
        // The vertical through x crosses the convex cell along [low, high].
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (unsigned int e = 0; e < 4; ++e)
          {
            // The edges in deal.II's numbering of a quadrilateral's vertices.
            static constexpr unsigned int ends[4][2] = {{0, 2},
                                                        {1, 3},
                                                        {0, 1},
                                                        {2, 3}};
            const Point<2>               &a          = c.vertices[ends[e][0]],
                           &b                        = c.vertices[ends[e][1]];
            if (a[0] == b[0])
              {
                if (a[0] == x[0])
                  for (const double y : {a[1], b[1]})
                    {
                      low  = std::min(low, y);
                      high = std::max(high, y);
                    }
                continue;
              }
            const double s = (x[0] - a[0]) / (b[0] - a[0]);
            if (s < 0 || s > 1)
              continue;
            const double y = a[1] + s * (b[1] - a[1]);
            low            = std::min(low, y);
            high           = std::max(high, y);
          }
        if (high > x[1])
          weight += c.unit_weight * (high - std::max(low, x[1]));
      }
    return parameters.initial_state.surcharge + weight;
  }


  SymmetricTensor<2, 3>
  KZeroStresses::stress(const Point<2>          &x,
                        const types::material_id material) const
  {
    const double          sigma_v = -overburden(x);
    const double          k0      = parameters.materials.at(material).k0;
    SymmetricTensor<2, 3> s;
    s[0][0] = k0 * sigma_v;
    s[1][1] = sigma_v;
    s[2][2] = k0 * sigma_v;
    return s;
  }
} // namespace thinlayer
