#ifndef thinlayer_discretisation_mode_constraints_h
#define thinlayer_discretisation_mode_constraints_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <thinlayer/discretisation/boundary_data.h>
#include <thinlayer/discretisation/kinematics.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The constraints of mode @p m. @p structural gets the element's own
   * lines (@p element_constraints: the serendipity centre nodes), the
   * components that play no part in the mode (u_theta for harmonic 0), and
   * on the axis r = 0 (boundary id @p axis, if >= 0) the conditions that
   * keep the field single-valued, which depend on the harmonic: harmonic 0
   * has no radial (symmetric series) or circumferential (antisymmetric)
   * movement there, harmonic 1 moves sideways rigidly (u_z = 0,
   * u_theta = -+ u_r), higher harmonics not at all. @p constraints gets
   * those and the homogeneous lines of the constrained components of
   * @p boundary_data: the space the mode's equations are solved in.
   */
  template <int dim>
  void
  make_mode_constraints(const DoFHandler<dim>           &dof_handler,
                        const Kinematics                &kinematics,
                        const unsigned int               m,
                        const int                        axis,
                        const AffineConstraints<double> &element_constraints,
                        const BoundaryData              &boundary_data,
                        AffineConstraints<double>       &structural,
                        AffineConstraints<double>       &constraints);
} // namespace thinlayer

#endif
