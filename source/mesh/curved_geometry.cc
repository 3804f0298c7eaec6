#include <deal.II/grid/manifold_lib.h>

#include <thinlayer/mesh/curved_geometry.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    /// The numbers between the braces of an unrolled entity's line.
    std::vector<std::string>
    braced_fields(const std::string &line)
    {
      std::vector<std::string> fields;
      const std::size_t        open  = line.find('{');
      const std::size_t        close = line.find('}', open);
      if (open == std::string::npos || close == std::string::npos)
        return fields;
      std::istringstream inside(line.substr(open + 1, close - open - 1));
      std::string        field;
      while (std::getline(inside, field, ','))
        fields.push_back(field);
      return fields;
    }

    /// The tag of an entity's line "Name(tag) = ...", or -1.
    int
    entity_tag(const std::string &line, const std::string &name)
    {
      if (line.rfind(name + "(", 0) != 0)
        return -1;
      try
        {
          return std::stoi(line.substr(name.size() + 1));
        }
      catch (const std::exception &)
        {
          return -1;
        }
    }

    /// The angle between two vectors.
    double
    angle(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
    {
      return std::atan2(cross_product_3d(a, b).norm(), a * b);
    }

    /// Whether @p radial, a vector from the arc's axis, lies between the
    /// arc's ends in angle (to 1e-8).
    bool
    within_span(const GeometryArc &arc, const Tensor<1, 3> &radial)
    {
      const Tensor<1, 3> s = arc.start - arc.centre, e = arc.end - arc.centre;
      return angle(s, radial) + angle(radial, e) <= angle(s, e) + 1e-8;
    }

    Point<3>
    in_3d(const Point<2> &p)
    {
      return Point<3>(p[0], p[1], 0);
    }

    Point<3>
    in_3d(const Point<3> &p)
    {
      return p;
    }
  } // namespace


  std::vector<GeometryArc>
  arcs_of_geometry(const std::string &unrolled)
  {
    std::map<int, Point<3>>         points;
    std::vector<std::array<int, 4>> circles;
    // The curves that bound a surface or are embedded in one: only those
    // are sides of cells. A construction circle that no surface uses
    // curves nothing, even where straight sides happen to end on it.
    std::set<int>      bounding;
    std::istringstream text(unrolled);
    std::string        line;
    while (std::getline(text, line))
      {
        const std::vector<std::string> fields = braced_fields(line);
        try
          {
            // gmsh 4 unrolls an embedded curve as "Line {5} In Surface
            // {1};", a loop as "Curve Loop(1) = {...};".
            if (line.rfind("Curve Loop(", 0) == 0 ||
                line.rfind("Line Loop(", 0) == 0 ||
                ((line.rfind("Line", 0) == 0 || line.rfind("Curve", 0) == 0) &&
                 line.find("In Surface") != std::string::npos))
              for (const std::string &field : fields)
                bounding.insert(std::abs(std::atoi(field.c_str())));
            if (const int tag = entity_tag(line, "Point");
                tag >= 0 && fields.size() >= 3)
              points[tag] = Point<3>(std::stod(fields[0]),
                                     std::stod(fields[1]),
                                     std::stod(fields[2]));
            else if (const int tag = entity_tag(line, "Circle");
                     tag >= 0 && fields.size() == 3)
              circles.push_back({{tag,
                                  std::abs(std::stoi(fields[0])),
                                  std::abs(std::stoi(fields[1])),
                                  std::abs(std::stoi(fields[2]))}});
          }
        catch (const std::exception &)
          {
            // A line in a form this reader does not know names no arc.
          }
      }

    std::vector<GeometryArc> arcs;
    for (const auto &[tag, start, centre, end] : circles)
      {
        if (bounding.count(tag) == 0 || points.count(start) == 0 ||
            points.count(centre) == 0 || points.count(end) == 0)
          continue;
        GeometryArc arc{tag,
                        points.at(centre),
                        points.at(start),
                        points.at(end),
                        points.at(start).distance(points.at(centre))};
        if (arc.radius > 0)
          arcs.push_back(arc);
      }
    return arcs;
  }


  template <int dim>
  unsigned int
  attach_arcs(Triangulation<dim> &tria, const std::vector<GeometryArc> &arcs)
  {
    std::vector<bool> used(arcs.size(), false);
    unsigned int      curved = 0;
    for (const auto &face : tria.active_face_iterators())
      for (unsigned int k = 0; k < arcs.size(); ++k)
        {
          const GeometryArc &arc = arcs[k];
          // The arc's plane normal: the axis an extruded arc sweeps along.
          const Tensor<1, 3> normal =
            cross_product_3d(arc.start - arc.centre, arc.end - arc.centre);
          if (normal.norm() <= 1e-12 * arc.radius * arc.radius)
            continue;
          const Tensor<1, 3> axis = normal / normal.norm();
          bool               on   = true;
          for (unsigned int v = 0; v < face->n_vertices() && on; ++v)
            {
              const Tensor<1, 3> w = in_3d(face->vertex(v)) - arc.centre;
              // In 2D every point lies in the arc's plane.
              const Tensor<1, 3> radial = w - (w * axis) * axis;
              on = (dim == 3 || std::abs(w * axis) <= 1e-8 * arc.radius) &&
                   std::abs(radial.norm() - arc.radius) <= 1e-8 * arc.radius &&
                   within_span(arc, radial);
            }
          if (!on)
            continue;
          face->set_all_manifold_ids(k + 1);
          used[k] = true;
          ++curved;
          break;
        }

    for (unsigned int k = 0; k < arcs.size(); ++k)
      if (used[k])
        {
          if constexpr (dim == 2)
            tria.set_manifold(k + 1,
                              PolarManifold<2>(Point<2>(arcs[k].centre[0],
                                                        arcs[k].centre[1])));
          else
            {
              const Tensor<1, 3> normal =
                cross_product_3d(arcs[k].start - arcs[k].centre,
                                 arcs[k].end - arcs[k].centre);
              tria.set_manifold(k + 1,
                                CylindricalManifold<3>(normal / normal.norm(),
                                                       arcs[k].centre));
            }
        }
    return curved;
  }


  template unsigned int
  attach_arcs(Triangulation<2> &, const std::vector<GeometryArc> &);
  template unsigned int
  attach_arcs(Triangulation<3> &, const std::vector<GeometryArc> &);
} // namespace thinlayer
