#ifndef thinlayer_mesh_mesh_checks_h
#define thinlayer_mesh_mesh_checks_h

#include <thinlayer/mesh/msh_file.h>

namespace thinlayer
{
  /**
   * @file
   * Checks of a gmsh mesh as read, before it is split along interface
   * curves and handed to deal.II, for meshes that deal.II accepts but
   * that would be analysed as another body.
   */

  /**
   * Refuse a geometry with a surface (a volume in 3D) that no physical
   * group names: gmsh leaves its cells out of the mesh once any physical
   * group exists, and the body silently loses them. @p unrolled is the
   * geometry as gmsh unrolls it (unrolled_geometry()); the InputError names
   * @p geometry and the entities. Nothing is refused where the unrolled
   * text lists no such entities (a geometry of the OpenCASCADE kernel,
   * written in its own commands).
   */
  void
  check_bodies_in_groups(const std::string &unrolled,
                         const std::string &geometry,
                         const unsigned int dim);

  /**
   * A conforming mesh: every cell side (a face in 3D) on the boundary of
   * the cells is a side of the body, so no node lies on it but its own
   * corners. A node inside such a side is a hanging node (cells that meet
   * at corners only, the small cells' nodes not joined to the large
   * cell's side), and a node at another node's place is a duplicate point
   * (the cells on either side of a crack not joined): both are refused,
   * naming the node, its place and the side, because the body they make
   * settles as if cut.
   */
  void
  check_conforming(const MshFile &mesh, const unsigned int dim);

  /**
   * The physical lines (2D) or faces (3D) of @p mesh that lie inside the
   * body, between two cells, where a boundary id means nothing: refused,
   * naming the physical group and what it may be instead (a boundary, or
   * interface elements with their section). @p interface_section is the
   * name of that section ("Interface").
   */
  void
  check_physical_faces_on_boundary(const MshFile     &mesh,
                                   const unsigned int dim,
                                   const std::string &interface_section);
} // namespace thinlayer

#endif
