#ifndef thinlayer_mesh_mesh_splitting_h
#define thinlayer_mesh_mesh_splitting_h

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
   * Throws InputError (naming @p mesh_file) for another format, or a
   * curve line without a cell on each side.
   */
  std::string
  split_along_curves(const std::string            &msh,
                     const std::set<unsigned int> &curves,
                     const std::string            &mesh_file);
} // namespace thinlayer

#endif
