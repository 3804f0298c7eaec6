#ifndef thinlayer_mesh_mesh_splitting_h
#define thinlayer_mesh_mesh_splitting_h

#include <thinlayer/mesh/msh_file.h>

#include <set>
#include <string>

namespace thinlayer
{
  /**
   * The gmsh mesh @p msh (format 2.2, first-order quadrilaterals with lines,
   * or hexahedra with quadrilaterals) cut along the physical curves (2D) or
   * surfaces (3D) @p curves, so that zero-thickness interface elements can
   * join the two sides (InterfaceElements):
   *
   * - around every node of the interface, its sides (lines in 2D,
   *   quadrilaterals in 3D) part the cells into sectors, the cells joined
   *   through the other sides at the node; each sector but one gets its own
   *   copy of the node (where an interface ends inside the body, a crack
   *   tip or front, the node has one sector and stays joined; corners and
   *   branches are cut as they divide the cells);
   * - each side of the interface becomes two, one with the nodes of the
   *   cell on each side, so that deal.II sees both sides as boundary faces
   *   with the interface's id; other sides and lines take the nodes of the
   *   first cell that has them.
   *
   * The nodes of the result are sorted by number, new nodes and elements
   * numbered on from the largest. Throws InputError (naming the mesh file)
   * for another format, or a side of the interface without a cell on each
   * side.
   */
  MshFile
  split_along_curves(const MshFile &msh, const std::set<unsigned int> &curves);
} // namespace thinlayer

#endif
