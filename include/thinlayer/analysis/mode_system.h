#ifndef thinlayer_analysis_mode_system_h
#define thinlayer_analysis_mode_system_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/discretisation/mode_vectors.h>
#include <thinlayer/parallel/mpi.h>
#include <thinlayer/solvers/amg_conjugate_gradient.h>
#include <thinlayer/solvers/distributed_factorisation.h>
#include <thinlayer/solvers/factorised_stiffness.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The linear system of one mode (one in plane strain, one per Fourier
   * harmonic): its constraints (the axis conditions depend on the
   * harmonic), its elastic stiffness and factorisation, and its loads at
   * unit load factor. Fixed once the analysis is set up; the state (the
   * displacements and forces of every mode) is the Analysis's, and what a
   * solution method iterates with is the method's.
   *
   * On one rank the stiffness is a SparseMatrix, factorised by CHOLMOD or
   * UMFPACK. On several, the condensed stiffness is a PETSc matrix
   * distributed by rows, and the raw stiffness is not kept: each rank adds
   * its cells' part of K u_prescribed to unit_rhs while assembling. That
   * matrix is then either split, factorised by MUMPS over every rank
   * (DistributedFactorisation), or, where the harmonics are spread over
   * the ranks, gathered whole on the harmonic's rank (owner) and
   * factorised there as on one rank; a solve is then the right-hand side
   * gathered on that rank, its substitution, and each rank's part sent
   * back.
   *
   * The vectors are ModeVectors: each rank holds its own DoFs' entries. The
   * constraints are kept whole on every rank; condense() and distribute()
   * act on the lines a rank owns, reading the entries those lines name as
   * ghosts (the analysis makes them ghosts).
   */
  struct ModeSystem
  {
    explicit ModeSystem(const FactorisedStiffness::Method method)
      : factorisation(method, FactorisedStiffness::elastic_pivot_ratio)
    {}

    /// Serendipity, dead-component and axis lines.
    AffineConstraints<double> structural_constraints;
    /// The above plus homogeneous Dirichlet lines: the solve's space.
    AffineConstraints<double> constraints;
    SparseMatrix<double>      stiffness;
    SparseMatrix<double>      condensed_stiffness;
    FactorisedStiffness       factorisation;
    /// What the current phase applies at unit load factor: the prescribed
    /// displacements, the loads, and f - K u_prescribed.
    ModeVector unit_prescribed_displacement;
    ModeVector unit_load;
    ModeVector unit_rhs;

    /// Prescribed displacements, tractions and their f - K u_prescribed.
    struct BoundaryValues
    {
      ModeVector prescribed_displacement;
      ModeVector load;
      ModeVector rhs;
    };
    /// The parts the phases combine into the above
    /// (StepAccess::begin_phase()): the Boundary sections' values (set 0)
    /// and each further loading phase's (set k: Phase k + 1), and the
    /// body's weight with the surcharge.
    std::vector<BoundaryValues> boundary_values;
    ModeVector                  weight_load;
    /// The external load held fixed while the phase runs: the loads of the
    /// phases before it at their end, or the weight that the initial
    /// stresses carry. Zero in a run of one phase.
    ModeVector held_load;

    /// On several ranks: the condensed stiffness (freed once factorised),
    /// and its factors (made only there: a PETSc object needs PETSc
    /// started, which one rank without mpirun never does).
    std::unique_ptr<PETScWrappers::MPI::SparseMatrix> distributed_stiffness;
    std::unique_ptr<DistributedFactorisation>         distributed_factorisation;

    /// With Solver/Linear solver = amg cg: the iterative solver (with its
    /// own copy of the condensed stiffness).
    std::unique_ptr<AmgConjugateGradient> iterative;

    /// On the rank that holds a spread mode's whole factor: the pattern of
    /// the gathered stiffness (whose values are freed once factorised).
    SparsityPattern whole_sparsity;

    /// On several ranks with the harmonics spread: the rank that holds
    /// this mode's whole factor (factorisation); else invalid.
    unsigned int owner = numbers::invalid_unsigned_int;

    /// Whether this mode's factor is whole on one of several ranks.
    bool
    spread() const
    {
      return owner != numbers::invalid_unsigned_int;
    }

    /**
     * Condense @p v, a vector of forces, with constraints (see
     * thinlayer::condense()). A collective call.
     */
    void
    condense(ModeVector &v) const;

    /**
     * Set each constrained DoF of @p v by its line of constraints (see
     * thinlayer::distribute()). A collective call.
     */
    void
    distribute(ModeVector &v) const;

    /// Solve K x = @p rhs in place with the elastic stiffness (@p rhs
    /// condensed). A collective call.
    void
    solve(ModeVector &rhs);

    /**
     * What this mode's elastic factor costs (the same on every rank; a
     * collective call where the mode is spread), or nothing known where
     * an iterative solver takes its place.
     */
    FactorCost
    elastic_cost() const;

    /// The first part of solve() for a spread mode: @p rhs whole on its
    /// owner, in whole_rhs. Collective; see IterationAccess::elastic_solve(),
    /// which lets the owners substitute at once.
    void
    gather_on_owner(const ModeVector &rhs);

    /// The second part: the owner substitutes whole_rhs.
    void
    substitute_on_owner();

    /// The last part: each rank's rows of the owner's solution in @p rhs.
    void
    scatter_from_owner(ModeVector &rhs) const;

    /// For a spread mode: where each rank's rows lie in the whole, and the
    /// whole right-hand side (then solution) on the owner.
    mpi::Parts     parts;
    Vector<double> whole_rhs;
  };
} // namespace thinlayer

#endif
