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
    /// A cell side on an interface.
    template <int dim>
    struct Side
    {
      typename DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                   face;
      types::boundary_id                             curve;
      Point<dim>                                     centre;
      /// The face's first two vertices: a 2D side's ends.
      std::array<Point<dim>, 2> ends;
    };

    bool
    lower_left(const Point<2> &a, const Point<2> &b, const double tolerance)
    {
      if (std::abs(a[0] - b[0]) > tolerance)
        return a[0] < b[0];
      return a[1] < b[1] - tolerance;
    }


    /// The interfaces' sides, each with the one facing it (the same centre
    /// on another cell), found along a sweep.
    template <int dim>
    std::vector<std::pair<Side<dim>, Side<dim>>>
    facing_pairs(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &curves,
                 const double                        tolerance,
                 const std::string                  &parameter_file)
    {
      std::vector<Side<dim>> sides;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) &&
              curves.count(cell->face(f)->boundary_id()))
            sides.push_back(
              {cell,
               f,
               cell->face(f)->boundary_id(),
               cell->face(f)->center(),
               {{cell->face(f)->vertex(0), cell->face(f)->vertex(1)}}});
      for (const types::boundary_id id : curves)
        if (std::none_of(sides.begin(), sides.end(), [id](const auto &s) {
              return s.curve == id;
            }))
          throw InputError(parameter_file,
                           InterfaceElementParameters::section(id),
                           std::string("a physical ") +
                             (dim == 2 ? "curve" : "surface") +
                             " of the mesh with cells on both sides; the "
                             "mesh has no " +
                             (dim == 2 ? "curve " : "surface ") +
                             std::to_string(id));

      // Sorted along an oblique direction, so that sides on a line or plane
      // of the axes rarely share a key while facing ones (the same centre)
      // always lie within twice the tolerance of each other.
      const auto key = [&](const unsigned int k) {
        const Point<dim> &c = sides[k].centre;
        return c[0] + 0.3183 * c[1] + (dim == 3 ? 0.1415 * c[dim - 1] : 0.);
      };
      std::vector<unsigned int> order(sides.size());
      for (unsigned int k = 0; k < order.size(); ++k)
        order[k] = k;
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return key(a) < key(b);
                       });
      std::vector<unsigned int> facing(sides.size(), sides.size());
      for (unsigned int a = 0; a < order.size(); ++a)
        for (unsigned int b = a + 1;
             b < order.size() && facing[order[a]] == sides.size() &&
             key(order[b]) - key(order[a]) < 2 * tolerance;
             ++b)
          {
            const auto &i = sides[order[a]], &j = sides[order[b]];
            if (facing[order[b]] == sides.size() && j.curve == i.curve &&
                j.cell != i.cell && j.centre.distance(i.centre) < tolerance)
              {
                facing[order[a]] = order[b];
                facing[order[b]] = order[a];
              }
          }

      std::vector<std::pair<Side<dim>, Side<dim>>> pairs;
      for (unsigned int i = 0; i < sides.size(); ++i)
        if (facing[i] == sides.size())
          {
            std::ostringstream message;
            message << "every cell side on the "
                    << (dim == 2 ? "curve" : "surface")
                    << " to face another, as along an interface through the "
                       "body; the side at ("
                    << sides[i].centre << ") faces none";
            throw InputError(parameter_file,
                             InterfaceElementParameters::section(
                               sides[i].curve),
                             message.str());
          }
        else if (i < facing[i])
          pairs.emplace_back(sides[i], sides[facing[i]]);
      return pairs;
    }


    /// The pairs on curves, chained into runs.
    std::vector<FacingSides<2>>
    chain_into_runs(const std::vector<std::pair<Side<2>, Side<2>>> &pairs,
                    const double                                    tolerance)
    {
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
            const Point<2> end    = pairs[k].first.ends[e];
            bool           shared = false;
            for (unsigned int l = 0; l < pairs.size() && !shared; ++l)
              if (l != k && curve_of(l) == curve_of(k))
                for (const Point<2> &other : pairs[l].first.ends)
                  shared = shared || same(other, end);
            if (!shared)
              starts.push_back({end, {k, e}});
          }
      std::sort(starts.begin(),
                starts.end(),
                [&](const auto &a, const auto &b) {
                  return lower_left(a.first, b.first, tolerance);
                });
      for (unsigned int k = 0; k < pairs.size(); ++k)
        starts.push_back({pairs[k].first.ends[0], {k, 0}});

      std::vector<FacingSides<2>>                result;
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
              done[k]               = true;
              const Side<2> &first  = pairs[k].first;
              const Side<2> &second = pairs[k].second;
              const auto     ends   = first.ends;
              const Point<2> exit   = same(ends[0], entry) ? ends[1] : ends[0];
              const Tensor<1, 2> chord = exit - entry;
              const Tensor<1, 2> normal({-chord[1], chord[0]});
              // The plus side is the one whose cell lies along the normal.
              const bool first_is_plus =
                (first.cell->center() - first.centre) * normal > 0;
              const Side<2> &plus  = first_is_plus ? first : second;
              const Side<2> &minus = first_is_plus ? second : first;
              result.push_back({plus.cell,
                                minus.cell,
                                plus.face,
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


    /// The pairs on surfaces, each with its plus side along the upward
    /// normal.
    std::vector<FacingSides<3>>
    orient_on_surfaces(const std::vector<std::pair<Side<3>, Side<3>>> &pairs)
    {
      std::vector<FacingSides<3>> result;
      for (const auto &[first, second] : pairs)
        {
          // The normal of the face's two chords through its centre, and on
          // which side of it the first cell lies.
          const auto   face = first.cell->face(first.face);
          Tensor<1, 3> n =
            cross_product_3d((face->vertex(1) + face->vertex(3)) -
                               (face->vertex(0) + face->vertex(2)),
                             (face->vertex(2) + face->vertex(3)) -
                               (face->vertex(0) + face->vertex(1)));
          n = upward(n / n.norm());
          const bool first_is_plus =
            (first.cell->center() - first.centre) * n > 0;
          const Side<3> &plus  = first_is_plus ? first : second;
          const Side<3> &minus = first_is_plus ? second : first;
          result.push_back({plus.cell,
                            minus.cell,
                            plus.face,
                            first.curve,
                            0,
                            0.,
                            first.centre,
                            first.centre});
        }
      return result;
    }
  } // namespace


  template <int dim>
  std::vector<FacingSides<dim>>
  pair_facing_sides(const DoFHandler<dim>              &dof_handler,
                    const std::set<types::boundary_id> &curves,
                    const std::string                  &parameter_file)
  {
    const double tolerance =
      1e-9 * GridTools::diameter(dof_handler.get_triangulation());
    const auto pairs =
      facing_pairs(dof_handler, curves, tolerance, parameter_file);
    if constexpr (dim == 2)
      return chain_into_runs(pairs, tolerance);
    else
      return orient_on_surfaces(pairs);
  }


  Tensor<1, 3>
  upward(const Tensor<1, 3> &n)
  {
    for (const unsigned int d : {1u, 0u, 2u})
      if (std::abs(n[d]) > 1e-10)
        return n[d] > 0 ? n : -n;
    return n;
  }


  Tensor<1, 3>
  first_tangent(const Tensor<1, 3> &n)
  {
    Tensor<1, 3> axis({1., 0., 0.});
    if (std::abs(n[0]) > 1 - 1e-10)
      axis = Tensor<1, 3>({0., 0., 1.});
    const Tensor<1, 3> t = axis - (axis * n) * n;
    return t / t.norm();
  }


  template std::vector<FacingSides<2>>
  pair_facing_sides(const DoFHandler<2> &,
                    const std::set<types::boundary_id> &,
                    const std::string &);
  template std::vector<FacingSides<3>>
  pair_facing_sides(const DoFHandler<3> &,
                    const std::set<types::boundary_id> &,
                    const std::string &);
} // namespace thinlayer
