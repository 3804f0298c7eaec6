#ifndef thinlayer_analysis_rigid_body_modes_h
#define thinlayer_analysis_rigid_body_modes_h

#include <deal.II/base/index_set.h>
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
   * Where the DoFs a rank owns lie: the support point (z = 0 on a 2D
   * mesh) and the component (0: x or r, 1: y or z, 2: theta or z) of each,
   * in the order of @p owned, and the mesh's dimension.
   */
  struct OwnedDofPlaces
  {
    IndexSet                  owned;
    std::vector<Point<3>>     points;
    std::vector<unsigned int> components;
    unsigned int              dimension = 2;
  };


  /**
   * The rigid-body motions of a plane-strain body (@p n_components 2) or a
   * solid one (a 3D mesh, @p n_components 3): the translations and the
   * rotations (one in the plane, three in space) about the centre of the
   * bounding box of every rank's support points, scaled by its size, on
   * this rank's DoFs (@p places; the vectors in the order of places.owned).
   * For a Fourier harmonic, whose rigid motions depend on its order, a
   * uniform displacement of each component. What algebraic multigrid must
   * represent on its coarse levels. A collective call.
   */
  std::vector<Vector<double>>
  rigid_body_motions(const OwnedDofPlaces &places,
                     const unsigned int    n_components);


  /// A rigid-body motion that the supports may leave free, and how firmly
  /// they hold it (free_rigid_body_motion()).
  struct FreeMotion
  {
    /// The motion, described; empty if the supports hold every one.
    std::string description;
    /// The smallest singular value of the scaled K R: about 1e-15 for a
    /// motion nothing holds, between that and 1e-9 for one held only
    /// through a stiffness that rounding swamps (a material 1e8 times
    /// softer than another, a nearly incompressible one).
    double resistance = 1;
  };

  /**
   * The rigid-body motion, if any, that the supports of a plane-strain or
   * solid body leave free: a description ("a rotation about (0.5, 0.5)",
   * "a rotation about the axis (0, 0, 1) through (0.5, 0.5, 0)", "a
   * translation in the direction (1, 0)"), or an empty one, and its
   * resistance.
   *
   * A free translation makes the stiffness exactly singular and its
   * factorisation fails; a free rotation does not: rounding leaves a pivot
   * of order 1e-16 of the others, the factorisation succeeds, and the
   * first solve returns displacements 1e10 times the elastic ones, which
   * look like a collapse at load 0. So the supports are checked directly.
   * The rigid motions (two translations and a rotation in the plane, three
   * of each in space) are taken with their constrained values set to zero
   * (the supports held);
   * a combination that the supports do not resist is one the condensed
   * stiffness maps to zero up to rounding: the smallest singular value of
   * K R, its columns scaled by |K| |R|, is below 1e-9 (rounding gives
   * 1e-15; a motion the supports hold, even at one node of a million,
   * gives 1e-4 or more).
   *
   * Each rank works on its own rows, and imports the motions of the
   * columns they name from those columns' owners; the products over the
   * rows are summed over the ranks. A collective call.
   *
   * @param places           this rank's DoFs, their points and components;
   * @param constraints      the constraints (those of this rank's DoFs at
   *                         least), Dirichlet lines (without entries)
   *                         counting as supports;
   * @param condensed_stiffness the stiffness condensed with them, its rows
   *                         those of places.owned.
   */
  FreeMotion
  free_rigid_body_motion(const OwnedDofPlaces            &places,
                         const AffineConstraints<double> &constraints,
                         const SparseMatrix<double>      &condensed_stiffness);

  FreeMotion
  free_rigid_body_motion(
    const OwnedDofPlaces                   &places,
    const AffineConstraints<double>        &constraints,
    const PETScWrappers::MPI::SparseMatrix &condensed_stiffness);
} // namespace thinlayer

#endif
