#ifndef thinlayer_mesh_splitting_h
#define thinlayer_mesh_splitting_h

#include <set>
#include <string>

namespace thinlayer
{
  /**
   * The gmsh mesh @p msh (format 2.2, first-order quadrilaterals and lines)
   * cut along the physical curves @p curves, so that zero-thickness
   * interface elements can join the two sides (ZeroThicknessElements):
   *
   * - every node of a curve is duplicated for the cells on the curve's left
   *   (seen along each of its line elements), except where the curve ends
   *   inside the body (a crack tip, where the sides stay joined);
   * - the curve's line elements are kept for the right side and repeated
   *   with the new nodes for the left, so that deal.II sees both sides as
   *   boundary faces with the curve's id;
   * - other line elements on the left side follow their cells' new nodes.
   *
   * Throws InputError (naming @p mesh_file) for another format, a curve
   * line without a cell on each side, or curves that branch or meet.
   */
  std::string
  split_along_curves(const std::string            &msh,
                     const std::set<unsigned int> &curves,
                     const std::string            &mesh_file);
} // namespace thinlayer

#endif
