#ifndef thinlayer_solution_methods_newton_h
#define thinlayer_solution_methods_newton_h

#include <thinlayer/analysis/coupled_system.h>
#include <thinlayer/solution_methods/return_mapping_method.h>

#include <memory>
#include <vector>

namespace thinlayer
{
  /**
   * Newton's method: the correction K_t^-1 r with the consistent tangent
   * K_t of the return mappings, assembled every iteration and solved
   * either by its factor (Solver/Newton corrections = factorised) or by
   * GMRES preconditioned by a factor kept from an earlier tangent (krylov:
   * an inexact Newton method, the tangent refactorised only where the kept
   * factor no longer serves), a backtracking line search on |r|_2, and, with
   * the load programme as given, the load step halved (Solver/Maximum
   * cut-backs) when an attempt does not converge in Solver/Maximum Newton
   * iterations (automatic stepping halves failed steps itself). An attempt
   * starts from the secant predictor (ReturnMappingMethod), its first
   * correction with the tangents at that predicted state.
   *
   * In the Fourier case the stations mix the harmonics, so the consistent
   * tangent couples them: it is one matrix over all modes, mode m's DoFs
   * shifted by m * n_dofs, each block condensed with its mode's
   * constraints (in plane strain, the one mode's matrix): a CoupledSystem,
   * to which every element group of the analysis adds its part
   * (ElementGroup::add_coupled_tangent()).
   */
  template <int dim>
  class NewtonMethod : public ReturnMappingMethod<dim>
  {
  public:
    using ReturnMappingMethod<dim>::ReturnMappingMethod;

    /// The coupled system and its sparsity.
    void
    initialize() override;

    /// What the tangent's factor costs: that of the last factorisation,
    /// nothing known before one.
    FactorCost
    tangent_cost() const;

    /// Yes: the tangent's factor solves for the load direction too.
    bool
    supports_work_control() const override;

    /// Also condenses the phase's unit loads for correct_load_factor().
    void
    set_work_control(const bool on) override;

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

    /**
     * When the residual stagnates (ConvergenceWatch::stagnating()): six
     * iterations that did not halve the best residual before them. While
     * a thin layer's set of yielding points settles, Newton's residual
     * wanders for a few iterations before it falls (four gave up a step
     * of Case 2 at aspect ratio 1000 that converges); an attempt given up
     * is only ever one the stepping halves anyway
     * (SolutionMethod::set_final_attempt()).
     */
    bool
    gives_up(const ConvergenceWatch &watch) const override;


    /// Resets the forcing term, and makes the final attempt's corrections
    /// exact.
    void
    start_attempt() override;

  private:
    /**
     * Assemble the tangent and solve for the correction: by a kept factor
     * and GMRES (Solver/Newton corrections = krylov) while GMRES reaches
     * the forcing term within Solver/Krylov iterations, else by
     * factorising the tangent (and keeping its factor). False if the
     * tangent is singular.
     */
    bool
    solve_correction(const ResidualNorms &norms, StepResult &result);

    /**
     * Under work control: the correction of the load factor, with which
     * the step's increment does the step's work, and the correction of
     * the displacements made to go with it. With a = K_t^-1 f (the factor
     * just made) and du the correction at the present load factor, the
     * load factor's correction dl makes f^T (u + du + dl a) the step's
     * work (Sysala et al.'s indirect continuation, a bordered system
     * solved by two substitutions); du gains dl a. False where f^T a is
     * not positive (the tangent no longer positive along the load).
     */
    bool
    correct_load_factor(double &dlambda);

    /**
     * The relative tolerance of the next Krylov solve (an inexact Newton
     * method's forcing term): Eisenstat and Walker's choice 2 from the
     * residual's last reduction, at most maximum_forcing_term, and no
     * tighter than the convergence test needs.
     */
    double
    next_forcing_term(const ResidualNorms &norms);

    /// The loosest forcing term: a correction that removes nine tenths
    /// of the residual of the linearised problem.
    static constexpr double maximum_forcing_term = 0.1;

    /// The residual |r|_2 of the last iteration of the attempt (0: none
    /// yet), and the last forcing term.
    double last_l2      = 0;
    double forcing_term = maximum_forcing_term;
    /// The last Krylov solve needed more than half its limit: factorise
    /// the next tangent.
    bool refactorise = false;
    /// The rest of the attempt solves its corrections by a factor of
    /// every tangent (start_attempt() and iterate() say when).
    bool exact_corrections = false;

    /// The tangent over all modes, and its factors.
    std::unique_ptr<CoupledSystem> system;
    /// Under work control, per mode: the unit loads condensed (by
    /// set_work_control()), and the tangent's response to them.
    ModeVectors load_rhs;
    ModeVectors load_response;
  };
} // namespace thinlayer

#endif
