#ifndef thinlayer_analysis_linear_solver_choice_h
#define thinlayer_analysis_linear_solver_choice_h

#include <thinlayer/parameters/parameters.h>

#include <string>

namespace thinlayer
{
  /**
   * The linear algebra a run uses for its elastic stiffness and Newton's
   * tangents, as Solver/Linear solver and the number of ranks decide it,
   * and what the run reports of it.
   */
  struct LinearSolverChoice
  {
    enum class Kind
    {
      /// Sparse Cholesky on one rank (LU where a tangent is unsymmetric).
      cholmod,
      /// Sparse LU on one rank.
      umfpack,
      /// MUMPS through PETSc, the factor split over the ranks.
      mumps,
      /// Conjugate gradients preconditioned by PETSc's GAMG.
      amg_cg
    };

    Kind kind;
    /// MUMPS's block low-rank compression: the dropping threshold of its
    /// blocks (CNTL(7)), relative to the matrix's norm; 0 for none.
    double block_low_rank_tolerance = 0;
    /// What was chosen and why, for the screen and summary.json.
    std::string description;
  };


  /**
   * What Solver/Linear solver means on @p n_ranks ranks for a mesh of
   * @p dimension.
   *
   * automatic: CHOLMOD on one rank; on several, MUMPS, with block low-rank
   * compression (Solver/Block low-rank tolerance) for a 3D mesh.
   * benchmarks/linear_solvers.py measures the choice: on one rank CHOLMOD
   * is the one direct solver; on several, compression shortens the
   * factorisation and the substitutions of a 3D factor, whose fronts are
   * large, with the same solution to its tolerance, and leaves a plane
   * (plane-strain or Fourier) factor as it is, its fronts too small to
   * compress, for a little more time per substitution. Conjugate gradients
   * with algebraic multigrid are never chosen: thin layers and distorted
   * cells make them iterate far longer than a factor takes, and Newton
   * factorises its tangents whatever the choice.
   *
   * Block low-rank on one rank is refused by SolverParameters::parse()
   * (MUMPS runs on several here).
   */
  LinearSolverChoice
  choose_linear_solver(const SolverParameters &parameters,
                       const unsigned int      n_ranks,
                       const unsigned int      dimension);
} // namespace thinlayer

#endif
