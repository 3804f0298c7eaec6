#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/mesh_checks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace thinlayer
{
  namespace
  {
    using Vector3 = std::array<double, 3>;

    Vector3
    minus(const Vector3 &a, const Vector3 &b)
    {
      return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
    }

    double
    dot(const Vector3 &a, const Vector3 &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    Vector3
    cross(const Vector3 &a, const Vector3 &b)
    {
      return {{a[1] * b[2] - a[2] * b[1],
               a[2] * b[0] - a[0] * b[2],
               a[0] * b[1] - a[1] * b[0]}};
    }

    double
    norm(const Vector3 &a)
    {
      return std::sqrt(dot(a, a));
    }

    std::string
    place(const Vector3 &x, const unsigned int dim)
    {
      std::ostringstream text;
      text.precision(8);
      text << '(' << x[0] << ", " << x[1];
      if (dim == 3)
        text << ", " << x[2];
      return text.str() + ")";
    }

    /// The gmsh type of a cell, and the corners of its sides (faces),
    /// in gmsh's node order.
    int
    cell_type(const unsigned int dim)
    {
      return dim == 2 ? 3 : 5;
    }

    const std::vector<std::vector<unsigned int>> &
    sides(const unsigned int dim)
    {
      static const std::vector<std::vector<unsigned int>> edges = {{0, 1},
                                                                   {1, 2},
                                                                   {2, 3},
                                                                   {3, 0}};
      static const std::vector<std::vector<unsigned int>> faces = {
        {0, 1, 2, 3},
        {4, 5, 6, 7},
        {0, 1, 5, 4},
        {1, 2, 6, 5},
        {2, 3, 7, 6},
        {3, 0, 4, 7}};
      return dim == 2 ? edges : faces;
    }

    std::vector<long>
    sorted(std::vector<long> nodes)
    {
      std::sort(nodes.begin(), nodes.end());
      return nodes;
    }

    /// A side of the cells: how many cells share it, its nodes in order,
    /// and the corners of (the last) cell it belongs to.
    struct Side
    {
      unsigned int      cells = 0;
      std::vector<long> nodes;
      std::vector<long> cell_corners;
    };

    /// The sides of the cells, by their sorted nodes.
    std::map<std::vector<long>, Side>
    count_sides(const MshFile &mesh, const unsigned int dim)
    {
      std::map<std::vector<long>, Side> count;
      for (const MshElement &e : mesh.elements)
        if (e.type == cell_type(dim))
          for (const auto &side : sides(dim))
            {
              std::vector<long> nodes;
              for (const unsigned int i : side)
                nodes.push_back(e.nodes[i]);
              Side &entry = count[sorted(nodes)];
              ++entry.cells;
              entry.nodes = nodes;
              entry.cell_corners.assign(e.nodes.begin(),
                                        e.nodes.begin() + (dim == 2 ? 4 : 8));
            }
      return count;
    }


    /**
     * The places of the nodes of a mesh's cells, in a grid of boxes for the
     * nodes near a place: boxes the size of the cells' mean spacing (the
     * extent over the number of nodes per direction), so that a side spans
     * a few boxes and a box holds a few nodes, whether the cells are thin
     * layers or blocks.
     */
    class NodePlaces
    {
    public:
      NodePlaces(const MshFile &mesh, const unsigned int dim)
        : mesh(mesh)
      {
        for (unsigned int k = 0; k < mesh.node_ids.size(); ++k)
          index[mesh.node_ids[k]] = k;
        std::vector<long> nodes;
        unsigned int      cell = 0;
        for (const MshElement &e : mesh.elements)
          if (e.type == cell_type(dim))
            {
              for (unsigned int i = 0; i < (dim == 2 ? 4u : 8u); ++i)
                {
                  nodes.push_back(e.nodes[i]);
                  cells_of[e.nodes[i]].push_back(cell);
                }
              ++cell;
            }
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        if (nodes.empty())
          return;
        low = high = at(nodes[0]);
        for (const long n : nodes)
          for (unsigned int d = 0; d < 3; ++d)
            {
              low[d]  = std::min(low[d], at(n)[d]);
              high[d] = std::max(high[d], at(n)[d]);
            }
        box = norm(minus(high, low)) /
              std::pow(static_cast<double>(nodes.size()), 1. / dim);
        if (!(box > 0) || !std::isfinite(box))
          return;
        for (const long n : nodes)
          grid[box_of(at(n))].push_back(n);
      }

      /// The place of node @p node.
      const Vector3 &
      at(const long node) const
      {
        const auto found = index.find(node);
        if (found == index.end())
          throw InputError(mesh.file,
                           "",
                           "an element names node " + std::to_string(node) +
                             ", which the mesh does not have");
        return mesh.positions[found->second];
      }

      /// Whether nodes @p a and @p b are corners of one cell.
      bool
      share_a_cell(const long a, const long b) const
      {
        const auto &x = cells_of.at(a);
        const auto &y = cells_of.at(b);
        return std::any_of(x.begin(), x.end(), [&](const unsigned int c) {
          return std::find(y.begin(), y.end(), c) != y.end();
        });
      }

      /// The mesh file, for messages.
      const std::string &
      file() const
      {
        return mesh.file;
      }

      /// Call @p visit(node) for the nodes in the boxes that the box from
      /// @p from to @p to touches.
      template <typename Visit>
      void
      near(const Vector3 &from, const Vector3 &to, const Visit &visit) const
      {
        if (grid.empty())
          return;
        const std::array<long, 3> first = box_of(from), last = box_of(to);
        for (long i = first[0]; i <= last[0]; ++i)
          for (long j = first[1]; j <= last[1]; ++j)
            for (long k = first[2]; k <= last[2]; ++k)
              if (const auto cell = grid.find({{i, j, k}}); cell != grid.end())
                for (const long n : cell->second)
                  visit(n);
      }

    private:
      std::array<long, 3>
      box_of(const Vector3 &x) const
      {
        std::array<long, 3> b;
        for (unsigned int d = 0; d < 3; ++d)
          b[d] = static_cast<long>(std::floor((x[d] - low[d]) / box));
        return b;
      }

      const MshFile                                      &mesh;
      std::unordered_map<long, unsigned int>              index;
      std::unordered_map<long, std::vector<unsigned int>> cells_of;
      Vector3                                             low{{0, 0, 0}};
      Vector3                                             high{{0, 0, 0}};
      double                                              box = 0;
      std::map<std::array<long, 3>, std::vector<long>>    grid;
    };


    /// Where @p p lies on the side with corners @p corner, to @p tolerance
    /// of its size: 0 off it, 1 at a corner, 2 on it elsewhere.
    int
    where_on(const std::vector<Vector3> &corner,
             const Vector3              &p,
             const double                tolerance)
    {
      if (corner.size() == 2)
        {
          const Vector3 edge = minus(corner[1], corner[0]);
          const Vector3 to_p = minus(p, corner[0]);
          const double  t    = dot(to_p, edge) / dot(edge, edge);
          const double  off  = norm(cross(edge, to_p)) / norm(edge);
          if (off > tolerance * norm(edge) || t < -tolerance ||
              t > 1 + tolerance)
            return 0;
          return (t <= tolerance || t >= 1 - tolerance) ? 1 : 2;
        }
      Vector3 normal =
        cross(minus(corner[2], corner[0]), minus(corner[3], corner[1]));
      const double area = norm(normal);
      const double size = std::max(norm(minus(corner[2], corner[0])),
                                   norm(minus(corner[3], corner[1])));
      if (!(area > 0))
        return 0;
      for (auto &x : normal)
        x /= area;
      if (std::abs(dot(normal, minus(p, corner[0]))) > tolerance * size)
        return 0;
      for (const Vector3 &c : corner)
        if (norm(minus(p, c)) <= tolerance * size)
          return 1;
      // On the inner side of every edge.
      for (unsigned int c = 0; c < 4; ++c)
        {
          const Vector3 edge = minus(corner[(c + 1) % 4], corner[c]);
          if (dot(cross(edge, minus(p, corner[c])), normal) <
              -tolerance * size * norm(edge))
            return 0;
        }
      return 2;
    }


    /// Refuse a node of @p places other than the corners of @p side's cell
    /// that lies on @p side (a side of one cell only).
    void
    check_boundary_side(const NodePlaces  &places,
                        const Side        &side,
                        const unsigned int dim)
    {
      const double         tolerance = 1e-9;
      std::vector<Vector3> corner;
      for (const long n : side.nodes)
        corner.push_back(places.at(n));
      Vector3 from = corner[0], to = corner[0];
      for (const auto &c : corner)
        for (unsigned int d = 0; d < 3; ++d)
          {
            from[d] = std::min(from[d], c[d]);
            to[d]   = std::max(to[d], c[d]);
          }
      const double margin = tolerance * norm(minus(to, from));
      for (unsigned int d = 0; d < 3; ++d)
        {
          from[d] -= margin;
          to[d] += margin;
        }
      std::string corners;
      for (const long c : side.nodes)
        corners += (corners.empty() ? "" : ", ") + std::to_string(c);
      places.near(from, to, [&](const long n) {
        // A corner of the side's own cell on the side makes that cell
        // degenerate, which the cell checks name.
        if (std::find(side.cell_corners.begin(), side.cell_corners.end(), n) !=
            side.cell_corners.end())
          return;
        const Vector3 &p  = places.at(n);
        const int      at = where_on(corner, p, tolerance);
        if (at == 1)
          {
            long twin = side.nodes[0];
            for (const long c : side.nodes)
              if (norm(minus(places.at(c), p)) <
                  norm(minus(places.at(twin), p)))
                twin = c;
            // Joined by a cell, the two make it degenerate (thinner than
            // rounding), which the cell checks name; not a crack.
            if (places.share_a_cell(twin, n))
              return;
            throw InputError(
              places.file(),
              "",
              "nodes " + std::to_string(twin) + " and " + std::to_string(n) +
                " lie at one place, " + place(p, dim) +
                " (a duplicate point): the cells on either side are not "
                "joined there, and the body would be cut; expected each "
                "point of the mesh once (in a .geo, no Point twice; gmsh's "
                "Coherence merges them)");
          }
        if (at == 2)
          throw InputError(
            places.file(),
            "",
            "node " + std::to_string(n) + " at " + place(p, dim) +
              " lies on the side of a cell (nodes " + corners +
              ") without being one of its corners: a hanging node, where "
              "cells meet at their corners only and are not joined, so the "
              "body would be cut; expected a conforming mesh, each cell side "
              "shared whole by the two cells beside it (in a .geo, curves "
              "and surfaces that share their points and transfinite counts "
              "that match)");
      });
    }
  } // namespace


  void
  check_bodies_in_groups(const std::string &unrolled,
                         const std::string &geometry,
                         const unsigned int dim)
  {
    const std::string  body     = dim == 2 ? "Surface" : "Volume";
    const std::string  physical = "Physical " + body + "(";
    std::set<long>     bodies, grouped;
    bool               any_group = false;
    std::istringstream text(unrolled);
    std::string        line;
    // "Plane Surface(3) = ...", "Surface(13) = ...", "Volume(1) = ...", and
    // "Physical Surface("soil", 1) = {3, 4};".
    const auto tag_after = [](const std::string &l, const std::string &head) {
      return std::strtol(l.c_str() + head.size(), nullptr, 10);
    };
    while (std::getline(text, line))
      {
        any_group = any_group || line.rfind("Physical ", 0) == 0;
        if (line.rfind(physical, 0) == 0)
          {
            const auto open  = line.find('{', line.find(")"));
            const auto close = line.find('}', open);
            if (open == std::string::npos || close == std::string::npos)
              continue;
            std::istringstream list(line.substr(open + 1, close - open - 1));
            for (std::string item; std::getline(list, item, ',');)
              grouped.insert(std::abs(std::strtol(item.c_str(), nullptr, 10)));
          }
        else if (line.rfind(body + "(", 0) == 0)
          bodies.insert(tag_after(line, body + "("));
        else if (dim == 2 && line.rfind("Plane Surface(", 0) == 0)
          bodies.insert(tag_after(line, "Plane Surface("));
      }
    // gmsh keeps every element where no physical group exists at all.
    if (!any_group)
      return;
    std::string lost;
    for (const long b : bodies)
      if (grouped.count(b) == 0)
        lost += (lost.empty() ? "" : ", ") + std::to_string(b);
    if (!lost.empty())
      throw InputError(
        geometry,
        "",
        std::string(dim == 2 ? "surface" : "volume") +
          (lost.find(',') == std::string::npos ? " " : "s ") + lost +
          " belong" + (lost.find(',') == std::string::npos ? "s" : "") +
          " to no Physical " + body +
          ", and gmsh leaves such cells out of the mesh; expected every " +
          (dim == 2 ? "surface" : "volume") +
          " of the body in a physical group (its material id)");
  }


  void
  check_conforming(const MshFile &mesh, const unsigned int dim)
  {
    const NodePlaces places(mesh, dim);
    for (const auto &[key, side] : count_sides(mesh, dim))
      if (side.cells == 1)
        check_boundary_side(places, side, dim);
  }


  void
  check_physical_faces_on_boundary(const MshFile     &mesh,
                                   const unsigned int dim,
                                   const std::string &interface_section)
  {
    const auto count = count_sides(mesh, dim);
    // Lines in 2D, quadrilateral faces in 3D.
    const int face_type = dim == 2 ? 1 : 3;
    for (const MshElement &e : mesh.elements)
      if (e.type == face_type && e.physical() != 0)
        {
          const auto side = count.find(
            sorted(std::vector<long>(e.nodes.begin(),
                                     e.nodes.begin() + (dim == 2 ? 2 : 4))));
          if (side == count.end() || side->second.cells < 2)
            continue;
          const std::string id = std::to_string(e.physical());
          throw InputError(
            mesh.file,
            "",
            std::string("physical ") + (dim == 2 ? "curve " : "surface ") + id +
              " runs inside the body (element " + std::to_string(e.id) +
              " lies between two cells), where a boundary condition means "
              "nothing; expected it on the boundary, for a 'Boundary " +
              id + "' section, or an '" + interface_section + " " + id +
              "' section for zero-thickness interface elements along it "
              "(the mesh is then split there)");
        }
  }
} // namespace thinlayer
