#ifndef thinlayer_mesh_curved_geometry_h
#define thinlayer_mesh_curved_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * A circular arc of a gmsh geometry: Circle(n) = {start, centre, end},
   * the arc from start to end (gmsh's arcs are shorter than a half circle).
   */
  struct GeometryArc
  {
    /// The curve's tag in the geometry.
    int      tag;
    Point<3> centre;
    Point<3> start;
    Point<3> end;
    double   radius;
  };


  /**
   * The circular arcs of a geometry, from gmsh's unrolled form of it
   * (gmsh -0 writes every entity with its points' coordinates evaluated,
   * whatever the .geo computed them from): the lines Point(p) = {x, y, z,
   * ...}; and Circle(n) = {start, centre, end};. Only circles that bound
   * a surface (a Curve Loop lists them) or are embedded in one are arcs
   * of the mesh; a construction circle that no surface uses curves
   * nothing. Other curves (lines, ellipses, splines) are not arcs and stay
   * as gmsh meshes them.
   */
  std::vector<GeometryArc>
  arcs_of_geometry(const std::string &unrolled);


  /**
   * Curve the cells of @p tria along @p arcs: every face (a cell side in 2D,
   * boundary or interior) whose two ends lie on an arc (at its radius from
   * its centre, to 1e-8 of the radius, and between its ends) gets that
   * arc's manifold, a PolarManifold about its centre. In 3D, every face
   * whose four corners lie on the cylinder an arc sweeps along its plane's
   * normal (an extruded arc), between the arc's ends in angle, gets a
   * CylindricalManifold about that axis, which keeps the face's edges
   * along the axis straight. The cells themselves stay flat: the
   * quadratic mapping then places their interior points by transfinite
   * interpolation of their curved sides. Returns the number of faces
   * curved.
   *
   * Why manifolds rather than gmsh's second-order nodes: deal.II's
   * triangulation keeps first-order cells, and a manifold serves every
   * place that asks for a point on the curve (the mapping's support points,
   * output with curved patches, refinement), from the geometry's exact
   * circle rather than from three nodes per side.
   */
  template <int dim>
  unsigned int
  attach_arcs(Triangulation<dim> &tria, const std::vector<GeometryArc> &arcs);
} // namespace thinlayer

#endif
