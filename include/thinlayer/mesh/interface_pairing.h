#ifndef thinlayer_mesh_interface_pairing_h
#define thinlayer_mesh_interface_pairing_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <set>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Two facing cell sides on a curve of a mesh split along it
   * (split_along_curves()), oriented along their run: the tangent points
   * from @p entry to @p exit, the normal is the tangent turned a quarter
   * turn anticlockwise, and the plus side's cell lies along the normal.
   */
  struct FacingSides
  {
    DoFHandler<2>::active_cell_iterator plus_cell;
    DoFHandler<2>::active_cell_iterator minus_cell;
    types::boundary_id                  curve;
    /// The run along the curve (chained through shared ends), and the arc
    /// length along it at @p entry.
    unsigned int run;
    double       arc_length;
    Point<2>     entry;
    Point<2>     exit;
  };


  /**
   * Every pair of facing sides on the curves @p curves (boundary faces with
   * those ids), chained into runs through shared ends, each run from its end
   * nearest the lower left (x before y), as LayerProfile orders a thin
   * layer. Throws InputError (naming @p parameter_file and the curve's
   * "Interface curve <id>" section) for a side that faces none, or a curve
   * the mesh does not have.
   */
  std::vector<FacingSides>
  pair_facing_sides(const DoFHandler<2>                &dof_handler,
                    const std::set<types::boundary_id> &curves,
                    const std::string                  &parameter_file);
} // namespace thinlayer

#endif
