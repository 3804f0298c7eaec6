#ifndef thinlayer_analysis_iteration_access_h
#define thinlayer_analysis_iteration_access_h

#include <thinlayer/analysis/analysis_view.h>

namespace thinlayer
{
  /**
   * What a solution method does to an analysis within a load step: it
   * sets the step's displacement increment, solves with the elastic
   * factors and runs the point rules; a method that cuts a step back
   * accepts its converged parts. Beginning phases, ending an attempt and
   * accepting or rejecting the step are the stepping's (StepAccess).
   */
  template <int dim>
  class IterationAccess : public AnalysisView<dim>
  {
  public:
    using AnalysisView<dim>::get_step_increment;

    /// The displacement increment of the current step, per mode, to be
    /// set.
    virtual ModeVectors &
    get_step_increment() = 0;

    /// Solve K_m x = @p rhs in place with mode @p m's elastic factors
    /// (@p rhs condensed with its constraints). A collective call.
    virtual void
    elastic_solve(const unsigned int m, ModeVector &rhs) = 0;

    /// The same for every mode m with @p rhs[m]: where the harmonics are
    /// spread over the ranks, their substitutions run at the same time.
    virtual void
    elastic_solve(ModeVectors &rhs) = 0;

    /**
     * The paper's viscoplastic point rule of every group for the step
     * increments; the body loads of the new viscoplastic strains are added
     * to @p body_load_change. Returns the number of yielding points and
     * stations.
     */
    virtual unsigned int
    viscoplastic_update(ModeVectors &body_load_change) = 0;

    /**
     * Stresses at every point and station by the return mapping of the
     * trial stresses of the step increments: sets the internal forces, and
     * @p stress_excess to the nodal forces of trial less returned stress.
     * With @p with_tangents, every group keeps its consistent tangents
     * for add_coupled_tangent(). Returns the number of yielding points
     * and stations.
     */
    virtual unsigned int
    return_mapping_update(const bool   with_tangents,
                          ModeVectors &stress_excess) = 0;

    /// Hand the DoFs of all modes (DoF m * n_dofs + i of mode m) of every
    /// cell and element this rank owns to @p add, every group's: the
    /// couplings of Newton's tangent.
    virtual void
    add_coupled_sparsity(const DofSink &add) = 0;

    /// Hand every group's tangent matrices of the last return mapping with
    /// tangents, of the cells and elements this rank owns, to @p add.
    virtual void
    add_coupled_tangent(const CellMatrixSink &add) = 0;

    /**
     * Make the current stresses the converged ones, add the step's
     * increment to the solution and its plastic strain to the total, and
     * take @p load_factor as the accepted load factor: for a method that
     * accepts a converged part of a step (cut-back).
     */
    virtual void
    accept_step(const double load_factor) = 0;
  };
} // namespace thinlayer

#endif
