#ifndef thinlayer_solution_methods_newton_h
#define thinlayer_solution_methods_newton_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <thinlayer/solution_methods/return_mapping_method.h>
#include <thinlayer/solvers/factorised_stiffness.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  /**
   * Newton's method: the correction K_t^-1 r with the consistent tangent
   * K_t of the return mappings, assembled and refactorised every
   * iteration, a backtracking line search on |r|_2, and, with the load
   * programme as given, the load step halved (Solver/Maximum cut-backs)
   * when an attempt does not converge in Solver/Maximum Newton iterations
   * (automatic stepping halves failed steps itself). An attempt starts
   * from the secant predictor (ReturnMappingMethod), its first correction
   * with the tangents at that predicted state.
   *
   * In the Fourier case the stations mix the harmonics, so the consistent
   * tangent couples them: it is one matrix over all modes, mode m's DoFs
   * shifted by m * n_dofs, each block condensed with its mode's
   * constraints (in plane strain, the one mode's matrix). The cell
   * matrices are computed in parallel over the point loop's chunks and
   * added in cell order.
   */
  template <int dim>
  class NewtonMethod : public ReturnMappingMethod<dim>
  {
  public:
    using ReturnMappingMethod<dim>::ReturnMappingMethod;

    /// The coupled system, and the tangents of the first iteration:
    /// elastic.
    void
    initialize() override;

    /// The tangents at the accepted state, to restart from after a failed
    /// attempt.
    void
    state_accepted() override;

    void
    state_rejected() override;

  protected:
    bool
    iterate(const double   target,
            ResidualNorms &norms,
            StepResult    &result) override;

    unsigned int
    max_iterations() const override;

    unsigned int
    max_cut_backs() const override;

    /// With the tangents at the predicted state, so that the first
    /// correction is Newton's (the accepted state's tangents made it
    /// overshoot: on Prandtl's footing most first iterations needed the
    /// line search).
    ResidualNorms
    starting_residual(const double target) override;


  private:
    /// Work space of one chunk of the cell tangents.
    struct ChunkScratch
    {
      /// Per mode and DoF, strain and stress; as six rows of raw
      /// components.
      std::vector<SymmetricTensor<2, 3>> strain, stress, part2;
      std::vector<double>                strain_rows, stress_rows;
    };

    /// The indices in the coupled system of cell @p c's DoFs, mode by
    /// mode.
    void
    cell_dofs(const unsigned int                    c,
              std::vector<types::global_dof_index> &dofs) const;

    /// The cell matrices of the tangent of the active cells [@p begin,
    /// @p end) into cell_matrices.
    void
    compute_cell_tangents(const unsigned int begin,
                          const unsigned int end,
                          ChunkScratch      &scratch);

    /// Whether every point and station of cell @p c has the elastic
    /// tangent.
    bool
    elastic_tangents(const unsigned int c) const;

    /// Assemble and factorise the tangent; false if the factorisation
    /// fails (a singular tangent at a mechanism).
    bool
    factorise_tangent();

    /// The consistent tangent at every point and station, and a copy at
    /// the accepted state.
    std::vector<SymmetricTensor<4, 3>> tangents;
    std::vector<SymmetricTensor<4, 3>> accepted_tangents;

    AffineConstraints<double>            constraints;
    SparsityPattern                      sparsity;
    SparseMatrix<double>                 tangent;
    std::unique_ptr<FactorisedStiffness> factorisation;
    /// Each cell's matrix of the tangent, computed in parallel for the
    /// cells with a plastic point; for the others the matrix with elastic
    /// tangents, computed once (near collapse the plastic zone is a small
    /// part of the body, and in Fourier scenes each cell matrix sums every
    /// station: most of Newton's time went into recomputing elastic ones).
    std::vector<FullMatrix<double>> cell_matrices;
    std::vector<FullMatrix<double>> elastic_cell_matrices;
    /// Per cell, of the last assembly: elastic_cell_matrices is used.
    std::vector<unsigned char> cell_is_elastic;
    std::vector<ChunkScratch>  chunk_scratch;
    /// The modes' residuals, then corrections, one after the other.
    Vector<double> coupled_vector;
  };
} // namespace thinlayer

#endif
