#ifndef thinlayer_analysis_rigid_body_modes_h
#define thinlayer_analysis_rigid_body_modes_h

#include <deal.II/base/point.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The rigid-body motions of a plane-strain body (@p n_components 2):
   * the two translations and the rotation about the centre of the bounding
   * box of @p support_points, scaled by its size, on the DoFs whose points
   * and components (0: x, 1: y) @p support_points and @p dof_component
   * give. With more components (a Fourier harmonic, whose rigid motions
   * depend on its order), a uniform displacement of each. What algebraic
   * multigrid must represent on its coarse levels.
   */
  std::vector<Vector<double>>
  rigid_body_motions(const std::vector<Point<2>>     &support_points,
                     const std::vector<unsigned int> &dof_component,
                     const unsigned int               n_components);


  /**
   * The rigid-body motion, if any, that the supports of a plane-strain body
   * leave free: a description ("a rotation about (0.5, 0.5)", "a
   * translation in the direction (1, 0)"), or an empty string.
   *
   * A free translation makes the stiffness exactly singular and its
   * factorisation fails; a free rotation does not: rounding leaves a pivot
   * of order 1e-16 of the others, the factorisation succeeds, and the
   * first solve returns displacements 1e10 times the elastic ones, which
   * look like a collapse at load 0. So the supports are checked directly.
   * The three rigid motions (two translations and a rotation) are taken
   * with their constrained values set to zero (the supports held);
   * a combination that the supports do not resist is one the condensed
   * stiffness maps to zero up to rounding: the smallest singular value of
   * K R, its columns scaled by |K| |R|, is below 1e-9 (rounding gives
   * 1e-15; a motion the supports hold, even at one node of a million,
   * gives 1e-4 or more).
   *
   * @param support_points   the point of every DoF;
   * @param dof_component    the component (0: x, 1: y) of every DoF;
   * @param constraints      the constraints, Dirichlet lines (without
   *                         entries) counting as supports;
   * @param condensed_stiffness the stiffness condensed with them.
   */
  std::string
  free_rigid_body_motion(const std::vector<Point<2>>     &support_points,
                         const std::vector<unsigned int> &dof_component,
                         const AffineConstraints<double> &constraints,
                         const SparseMatrix<double>      &condensed_stiffness);

  /// The same with the condensed stiffness distributed over the ranks by
  /// rows (a collective call; the answer on every rank).
  std::string
  free_rigid_body_motion(
    const std::vector<Point<2>>            &support_points,
    const std::vector<unsigned int>        &dof_component,
    const AffineConstraints<double>        &constraints,
    const PETScWrappers::MPI::SparseMatrix &condensed_stiffness);
} // namespace thinlayer

#endif
