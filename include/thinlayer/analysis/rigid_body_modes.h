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
   * Where the DoFs a rank owns lie: the support point and the component
   * (0: x or r, 1: y or z, 2: theta) of each, in the order of @p owned.
   */
  struct OwnedDofPlaces
  {
    IndexSet                  owned;
    std::vector<Point<2>>     points;
    std::vector<unsigned int> components;
  };


  /**
   * The rigid-body motions of a plane-strain body (@p n_components 2):
   * the two translations and the rotation about the centre of the bounding
   * box of every rank's support points, scaled by its size, on this rank's
   * DoFs (@p places; the vectors in the order of places.owned). With more
   * components (a Fourier harmonic, whose rigid motions depend on its
   * order), a uniform displacement of each. What algebraic multigrid must
   * represent on its coarse levels. A collective call.
   */
  std::vector<Vector<double>>
  rigid_body_motions(const OwnedDofPlaces &places,
                     const unsigned int    n_components);


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
  std::string
  free_rigid_body_motion(const OwnedDofPlaces            &places,
                         const AffineConstraints<double> &constraints,
                         const SparseMatrix<double>      &condensed_stiffness);

  std::string
  free_rigid_body_motion(
    const OwnedDofPlaces                   &places,
    const AffineConstraints<double>        &constraints,
    const PETScWrappers::MPI::SparseMatrix &condensed_stiffness);
} // namespace thinlayer

#endif
