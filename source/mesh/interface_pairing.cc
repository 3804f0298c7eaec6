#include <deal.II/grid/grid_tools.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <array>
#include <map>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    using CellIterator = DoFHandler<2>::active_cell_iterator;

    /// A cell side on an interface curve.
    struct Side
    {
      CellIterator            cell;
      types::boundary_id      curve;
      Point<2>                centre;
      std::array<Point<2>, 2> ends;
    };

    bool
    lower_left(const Point<2> &a, const Point<2> &b, const double tolerance)
    {
      if (std::abs(a[0] - b[0]) > tolerance)
        return a[0] < b[0];
      return a[1] < b[1] - tolerance;
    }


    /// The curves' sides, each with the one facing it.
    std::vector<std::pair<Side, Side>>
    facing_pairs(const DoFHandler<2>                &dof_handler,
                 const std::set<types::boundary_id> &curves,
                 const double                        tolerance,
                 const std::string                  &parameter_file)
    {
      std::vector<Side> sides;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              curves.count(cell->face(f)->boundary_id()))
            sides.push_back(
              {cell,
               cell->face(f)->boundary_id(),
               cell->face(f)->center(),
               {{cell->face(f)->vertex(0), cell->face(f)->vertex(1)}}});
      for (const types::boundary_id id : curves)
        if (std::none_of(sides.begin(), sides.end(), [id](const Side &s) {
              return s.curve == id;
            }))
          throw InputError(parameter_file,
                           InterfaceElementParameters::section(id),
                           "a physical curve of the mesh with cells on both "
                           "sides; the mesh has no curve " +
                             std::to_string(id));

      std::vector<std::pair<Side, Side>> pairs;
      std::vector<bool>                  paired(sides.size(), false);
      for (unsigned int i = 0; i < sides.size(); ++i)
        if (!paired[i])
          {
            for (unsigned int j = i + 1; j < sides.size() && !paired[i]; ++j)
              if (!paired[j] && sides[j].curve == sides[i].curve &&
                  sides[j].cell != sides[i].cell &&
                  sides[j].centre.distance(sides[i].centre) < tolerance)
                {
                  paired[i] = paired[j] = true;
                  pairs.emplace_back(sides[i], sides[j]);
                }
            if (!paired[i])
              {
                std::ostringstream message;
                message << "every cell side on the curve to face another, as "
                           "along a curve through the body; the side at ("
                        << sides[i].centre << ") faces none";
                throw InputError(parameter_file,
                                 InterfaceElementParameters::section(
                                   sides[i].curve),
                                 message.str());
              }
          }
      return pairs;
    }
  } // namespace


  std::vector<FacingSides>
  pair_facing_sides(const DoFHandler<2>                &dof_handler,
                    const std::set<types::boundary_id> &curves,
                    const std::string                  &parameter_file)
  {
    const double tolerance =
      1e-9 * GridTools::diameter(dof_handler.get_triangulation());
    const auto pairs =
      facing_pairs(dof_handler, curves, tolerance, parameter_file);
    const auto same = [&](const Point<2> &a, const Point<2> &b) {
      return a.distance(b) < tolerance;
    };
    const auto curve_of = [&](const unsigned int k) {
      return pairs[k].first.curve;
    };

    // Runs start at a free end (one no other pair of the curve shares),
    // the one nearest the lower left first; closed loops last.
    std::vector<std::pair<Point<2>, std::pair<unsigned int, unsigned int>>>
      starts; // (end, (pair, which end))
    for (unsigned int k = 0; k < pairs.size(); ++k)
      for (unsigned int e = 0; e < 2; ++e)
        {
          const Point<2> &end    = pairs[k].first.ends[e];
          bool            shared = false;
          for (unsigned int l = 0; l < pairs.size() && !shared; ++l)
            if (l != k && curve_of(l) == curve_of(k))
              for (const Point<2> &other : pairs[l].first.ends)
                shared = shared || same(other, end);
          if (!shared)
            starts.push_back({end, {k, e}});
        }
    std::sort(starts.begin(), starts.end(), [&](const auto &a, const auto &b) {
      return lower_left(a.first, b.first, tolerance);
    });
    for (unsigned int k = 0; k < pairs.size(); ++k)
      starts.push_back({pairs[k].first.ends[0], {k, 0}});

    std::vector<FacingSides>                   result;
    std::vector<bool>                          done(pairs.size(), false);
    std::map<types::boundary_id, unsigned int> runs;
    for (const auto &start : starts)
      {
        unsigned int k = start.second.first;
        if (done[k])
          continue;
        Point<2>           entry = pairs[k].first.ends[start.second.second];
        const unsigned int run   = runs[curve_of(k)]++;
        double             arc   = 0;
        while (true)
          {
            done[k]              = true;
            const Side    &first = pairs[k].first;
            const Point<2> exit =
              same(first.ends[0], entry) ? first.ends[1] : first.ends[0];
            const Tensor<1, 2> chord = exit - entry;
            const Tensor<1, 2> normal({-chord[1], chord[0]});
            // The plus side is the one whose cell lies along the normal.
            const bool first_is_plus =
              (first.cell->center() - first.centre) * normal > 0;
            result.push_back({first_is_plus ? first.cell : pairs[k].second.cell,
                              first_is_plus ? pairs[k].second.cell : first.cell,
                              first.curve,
                              run,
                              arc,
                              entry,
                              exit});
            arc += chord.norm();

            // The next pair of this curve sharing the exit.
            int next = -1;
            for (unsigned int l = 0; l < pairs.size() && next < 0; ++l)
              if (!done[l] && curve_of(l) == first.curve)
                for (const Point<2> &e : pairs[l].first.ends)
                  if (same(e, exit))
                    next = l;
            if (next < 0)
              break;
            k     = next;
            entry = exit;
          }
      }
    return result;
  }
} // namespace thinlayer
