#ifndef thinlayer_mesh_mesh_splitting_h
#define thinlayer_mesh_mesh_splitting_h

#include <thinlayer/mesh/msh_file.h>

#include <set>
#include <string>

namespace thinlayer
{
  /**
   * The gmsh mesh @p msh (format 2.2, first-order quadrilaterals and lines)
   * cut along the physical curves @p curves, so that zero-thickness
   * interface elements can join the two sides (InterfaceElements):
   *
   * - around every node of a curve, the curves' edges part the cells into
   *   sectors; each sector but one gets its own copy of the node (a curve's
   *   end inside the body, a crack tip, has one sector and stays joined;
   *   corners and branches are cut as they divide the cells);
   * - each curve line becomes two, one with the nodes of the cell on each
   *   side, so that deal.II sees both sides as boundary faces with the
   *   curve's id; other lines take their cell's nodes.
   *
   * The nodes of the result are sorted by number, new nodes and lines
   * numbered on from the largest. Throws InputError (naming the mesh file)
   * for another format, or a curve line without a cell on each side.
   */
  MshFile
  split_along_curves(const MshFile &msh, const std::set<unsigned int> &curves);
} // namespace thinlayer

#endif
