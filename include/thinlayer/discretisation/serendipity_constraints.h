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
   * Lines are only added for DoFs not yet constrained; call this before
   * adding hanging-node and Dirichlet constraints, then close().
   */
  template <int dim>
  void
  make_serendipity_constraints(const DoFHandler<dim>     &dof_handler,
                               AffineConstraints<double> &constraints);
} // namespace thinlayer

#endif
