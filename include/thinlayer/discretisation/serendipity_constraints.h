#ifndef thinlayer_discretisation_serendipity_constraints_h
#define thinlayer_discretisation_serendipity_constraints_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Turn a continuous Q2 space (FE_Q<dim>(2), or an FESystem of them) into
   * the quadratic serendipity space: the 8-node quadrilateral in 2D, the
   * 20-node hexahedron in 3D. deal.II has no serendipity element, and the
   * paper's results depend on it, so we obtain it by constraint.
   *
   * For every cell and component, the node at the centre of each quad (the
   * cell centre in 2D; face centres and the cell centre in 3D) is made the
   * value the serendipity interpolant takes there:
   * @f[
   *   u_\text{centre} = -\tfrac14 \sum_\text{corners} u
   *                     + \tfrac12 \sum_\text{mid-sides} u
   * @f]
   * (in 3D the cell centre gets -1/4 of the 8 corners and +1/4 of the 12
   * mid-edges). This removes exactly the modes outside the serendipity
   * space (the xi^2 eta^2 mode in 2D), so the constrained space equals the
   * isoparametric Q8/Q20 on parallelograms and parallelepipeds.
   *
   * Lines are only added for DoFs not yet constrained: call this after
   * adding hanging-node constraints (make_element_constraints()) and
   * before the Dirichlet ones, then close().
   */
  template <int dim>
  void
  make_serendipity_constraints(const DoFHandler<dim>     &dof_handler,
                               AffineConstraints<double> &constraints);

  /**
   * The constraints of the element's space on a mesh that may have hanging
   * nodes (a refined mesh): the hanging-node lines of the Q2 space, then,
   * where @p serendipity, the centre lines above for the centres that are
   * not hanging themselves. The space is conforming and serendipity on
   * every cell: a hanging side (a child's face in 3D) takes the trace of
   * its coarse neighbour, a serendipity function of the coarse side, and
   * the serendipity space is closed under the affine map onto a half side
   * (a quarter face), so the child's side is serendipity too, its centre
   * the value the centre rule gives it.
   */
  template <int dim>
  void
  make_element_constraints(const DoFHandler<dim>     &dof_handler,
                           const bool                 serendipity,
                           AffineConstraints<double> &constraints);
} // namespace thinlayer

#endif
