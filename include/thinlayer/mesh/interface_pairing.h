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
   * Two facing cell sides on an interface of a mesh split along it
   * (split_along_curves()): two edges on a curve of a 2D mesh, two faces on
   * a surface of a 3D one. The plus side's cell lies along the interface's
   * normal n:
   * - on a curve the sides are oriented along their run: the tangent points
   *   from @p entry to @p exit and n is it turned a quarter turn
   *   anticlockwise;
   * - on a surface n points up (n_y > 0; in a vertical surface along +x,
   *   then +z), as the profile of a thin layer of hexahedra has it.
   */
  template <int dim>
  struct FacingSides
  {
    typename DoFHandler<dim>::active_cell_iterator plus_cell;
    typename DoFHandler<dim>::active_cell_iterator minus_cell;
    /// The face of @p plus_cell on the interface.
    unsigned int       plus_face;
    types::boundary_id curve;
    /// On a curve (2D): the run along it (chained through shared ends),
    /// the arc length along it at @p entry, and the side's two ends. On a
    /// surface: run and arc length 0, entry and exit the face's centre.
    unsigned int run;
    double       arc_length;
    Point<dim>   entry;
    Point<dim>   exit;
  };


  /**
   * Every pair of facing sides on the interfaces @p curves (boundary faces
   * with those ids). Along curves, chained into runs through shared ends,
   * each run from its end nearest the lower left (x before y), as
   * LayerProfile orders a thin layer; on surfaces in the order of the
   * cells. Throws InputError (naming @p parameter_file and the interface's
   * "Interface <id>" section) for a side that faces none, or an id
   * the mesh does not have.
   */
  template <int dim>
  std::vector<FacingSides<dim>>
  pair_facing_sides(const DoFHandler<dim>              &dof_handler,
                    const std::set<types::boundary_id> &curves,
                    const std::string                  &parameter_file);


  /**
   * The unit normal @p n of an interface surface made to point up (n_y >
   * 0), or where it lies in the plane normal to y (to rounding) along +x,
   * then +z: the one convention of the thin layers' and the interface
   * elements' profiles in 3D.
   */
  Tensor<1, 3>
  upward(const Tensor<1, 3> &n);

  /**
   * The first tangent t1 of an interface surface of unit normal @p n: x
   * projected onto the surface, or z where the surface is normal to x. The
   * second is t2 = t1 x n.
   */
  Tensor<1, 3>
  first_tangent(const Tensor<1, 3> &n);
} // namespace thinlayer

#endif
