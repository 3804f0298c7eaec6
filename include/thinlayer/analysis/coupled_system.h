#ifndef thinlayer_analysis_coupled_system_h
#define thinlayer_analysis_coupled_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/elements/element_group.h>
#include <thinlayer/solvers/distributed_factorisation.h>
#include <thinlayer/solvers/factorised_stiffness.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Newton's linear system over all modes: the consistent tangent, which
   * couples the Fourier harmonics through the stations (in plane strain,
   * the one mode's matrix), each mode's block condensed with its mode's
   * constraints, factorised at every iteration.
   *
   * The element groups hand their matrices with DoF m * n + i for DoF i of
   * mode m (ElementGroup::add_coupled_tangent()). On one rank that is the
   * system's numbering, the matrix a SparseMatrix factorised by CHOLMOD or
   * UMFPACK. On several, the matrix is a PETSc matrix distributed by rows
   * and factorised by MUMPS, whose ranks need contiguous rows: rank r's
   * DoFs of all modes are numbered together, mode by mode, after those of
   * the ranks before it (with one mode, the same numbering). MUMPS keeps
   * its symbolic analysis from one factorisation to the next, as CHOLMOD
   * does on one rank: the pattern never changes.
   */
  class CoupledSystem
  {
  public:
    /**
     * The system of the modes whose constraints @p mode_constraints gives
     * (each over the same @p n_dofs DoFs), with every rank's DoFs in
     * @p owned_per_rank (empty on one rank). @p symmetric: the tangent is
     * symmetric (every flow rule associated), factorised by Cholesky
     * (CHOLMOD where @p method says so, MUMPS's L D L^T) rather than LU.
     * @p block_low_rank_tolerance: MUMPS's compression
     * (DistributedFactorisation), 0 for none.
     */
    CoupledSystem(
      const std::vector<const AffineConstraints<double> *> &mode_constraints,
      const types::global_dof_index                         n_dofs,
      const std::vector<IndexSet>                          &owned_per_rank,
      const bool                                            symmetric,
      const FactorisedStiffness::Method                     method,
      const double block_low_rank_tolerance = 0);

    ~CoupledSystem();

    /// The sparsity of the DoFs that @p add_dofs hands to its argument (of
    /// every cell or element this rank owns, in the m * n + i numbering).
    void
    reinit(const std::function<void(const DofSink &)> &add_dofs);

    /**
     * Assemble the tangent whose matrices @p add_matrices hands to its
     * argument (every cell or element this rank owns, in the m * n + i
     * numbering) and factorise it. Returns false if it is singular (or, by
     * Cholesky, not positive definite): a mechanism has formed.
     */
    bool
    factorise(const std::function<void(const CellMatrixSink &)> &add_matrices);

    /// Assemble the tangent whose matrices @p add_matrices hands to its
    /// argument, as factorise() does, without factorising it: the operator
    /// of solve_iteratively().
    void
    assemble(const std::function<void(const CellMatrixSink &)> &add_matrices);

    /**
     * Factorise the matrix assemble() left. Returns false if it is
     * singular; the system then holds no factor (has_factor()) until a
     * later factorisation succeeds.
     */
    bool
    factorise_assembled();

    /// Whether a factor of some earlier tangent is held.
    bool
    has_factor() const;

    /// What the held factor cost and what a substitution with it costs;
    /// nothing known while no factor is held.
    FactorCost
    factor_cost() const;

    /// @p correction = K_t^-1 @p residual, mode by mode, by the held
    /// factor, with the constrained DoFs set from the constraints.
    void
    solve(const ModeVectors &residual, ModeVectors &correction);

    /**
     * What preconditions solve_iteratively(): the factor this system
     * holds, of an earlier tangent, or the caller's solve of every mode
     * with its elastic factor in place (each mode's block of the elastic
     * stiffness, the tangent of a body that has not yielded).
     */
    using ModeSolve = std::function<void(ModeVectors &)>;

    /**
     * @p correction = K_t^-1 @p residual for the tangent of the last
     * assemble(), by GMRES preconditioned (on the right, so that its
     * residual is the true one) by the held factor or by @p elastic_solve
     * if given, to a residual @p relative_tolerance times |residual|_2.
     * Returns the GMRES iterations, or nothing, with @p correction
     * undefined, if it did not get there within @p max_iterations: the
     * preconditioner no longer serves, and the tangent is to be
     * factorised.
     */
    std::optional<unsigned int>
    solve_iteratively(const ModeVectors &residual,
                      ModeVectors       &correction,
                      const double       relative_tolerance,
                      const unsigned int max_iterations,
                      const ModeSolve   *elastic_solve = nullptr);

  private:
    /// The system's DoF of DoF @p i of mode @p m.
    types::global_dof_index
    index(const unsigned int m, const types::global_dof_index i) const;

    /// Where this rank's @p k-th DoF of mode @p m is in the system's
    /// vector (vector).
    types::global_dof_index
    row(const unsigned int m, const types::global_dof_index k) const;

    /// The residual's rows into the system's vector, and the system's
    /// vector back into a correction, with its constrained DoFs set.
    void
    gather(const ModeVectors &residual);
    void
    scatter(ModeVectors &correction);

    /// @p dofs, in the m * n + i numbering, in the system's.
    const std::vector<types::global_dof_index> &
    renumbered(const std::vector<types::global_dof_index> &dofs) const;

    const unsigned int            n_modes;
    const types::global_dof_index n;
    /// Where each rank's DoFs start, and how many it has (several ranks).
    std::vector<types::global_dof_index> first_dof, n_owned;
    /// This rank's DoFs of one mode (several ranks).
    types::global_dof_index rows_of_a_mode = 0;
    /// Each rank's rows of the system (several ranks).
    std::vector<IndexSet> rows_per_rank;
    /// This rank's rows of every DoF it holds (several ranks).
    IndexSet held_rows;
    /// Whether the system's numbering is the m * n + i one.
    bool identity;

    /// Each mode's constraints, for a correction's lines on many ranks.
    std::vector<const AffineConstraints<double> *> mode_constraints;

    AffineConstraints<double> constraints;

    SparsityPattern                      sparsity;
    SparseMatrix<double>                 matrix;
    std::unique_ptr<FactorisedStiffness> factorisation;

    std::unique_ptr<PETScWrappers::MPI::SparseMatrix> distributed_matrix;
    std::unique_ptr<DistributedFactorisation>         distributed_factorisation;

    bool held_factor = false;

    Vector<double> vector;
    /// The modes' vectors of an elastic preconditioner's solve, and
    /// GMRES's solution (and right-hand side, on several ranks), kept from
    /// one solve to the next.
    ModeVectors                                  mode_work;
    Vector<double>                               krylov_solution;
    std::unique_ptr<PETScWrappers::MPI::Vector>  distributed_rhs;
    std::unique_ptr<PETScWrappers::MPI::Vector>  distributed_solution;
    mutable std::vector<types::global_dof_index> renumbered_dofs;
  };
} // namespace thinlayer

#endif
