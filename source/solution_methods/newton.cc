#include <thinlayer/solution_methods/newton.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace thinlayer
{
  template <int dim>
  void
  NewtonMethod<dim>::initialize()
  {
    ReturnMappingMethod<dim>::initialize();
    IterationAccess<dim> &analysis = this->analysis;

    std::vector<const AffineConstraints<double> *> mode_constraints;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      mode_constraints.push_back(&analysis.get_mode_system(m).constraints);
    // A non-associated flow rule makes the tangent unsymmetric. The
    // tangent is factorised with amg cg too (by CHOLMOD where symmetric).
    const LinearSolverChoice &linear_solver = analysis.get_linear_solver();
    system =
      std::make_unique<CoupledSystem>(mode_constraints,
                                      analysis.get_dof_handler().n_dofs(),
                                      analysis.get_owned_per_rank(),
                                      analysis.all_laws_associated(),
                                      linear_solver.kind ==
                                          LinearSolverChoice::Kind::umfpack
                                        ? FactorisedStiffness::Method::umfpack
                                        : FactorisedStiffness::Method::cholmod,
                                      linear_solver.block_low_rank_tolerance);
    system->reinit(
      [&analysis](const DofSink &add) { analysis.add_coupled_sparsity(add); });
    load_rhs      = analysis.new_mode_vectors();
    load_response = load_rhs;
  }


  template <int dim>
  bool
  NewtonMethod<dim>::supports_work_control() const
  {
    return true;
  }


  template <int dim>
  void
  NewtonMethod<dim>::set_work_control(const bool on)
  {
    ReturnMappingMethod<dim>::set_work_control(on);
    // The phase's loads stay as they are while it runs: condensed once.
    IterationAccess<dim> &analysis = this->analysis;
    if (on)
      for (unsigned int m = 0; m < analysis.n_modes(); ++m)
        {
          const ModeSystem &mode = analysis.get_mode_system(m);
          load_rhs[m]            = mode.unit_load;
          mode.condense(load_rhs[m]);
        }
  }


  template <int dim>
  bool
  NewtonMethod<dim>::correct_load_factor(double &dlambda)
  {
    IterationAccess<dim> &analysis = this->analysis;
    system->solve(load_rhs, load_response);
    const double along_load = this->work_of(load_response);
    if (!(along_load > 0) || !std::isfinite(along_load))
      return false;
    const double work = this->work_of(analysis.get_step_increment()) +
                        this->work_of(this->correction);
    dlambda = (this->step_work - work) / along_load;
    for (unsigned int m = 0; m < analysis.n_modes(); ++m)
      this->correction[m].add(dlambda, load_response[m]);
    return true;
  }


  template <int dim>
  FactorCost
  NewtonMethod<dim>::tangent_cost() const
  {
    return system ? system->factor_cost() : FactorCost();
  }


  template <int dim>
  unsigned int
  NewtonMethod<dim>::max_iterations() const
  {
    return this->parameters.max_newton_iterations;
  }


  template <int dim>
  unsigned int
  NewtonMethod<dim>::max_cut_backs() const
  {
    return this->parameters.max_cut_backs;
  }


  template <int dim>
  ResidualNorms
  NewtonMethod<dim>::starting_residual(const double target)
  {
    return this->evaluate_residual(target, /*tangents=*/true);
  }


  template <int dim>
  bool
  NewtonMethod<dim>::gives_up(const ConvergenceWatch &watch) const
  {
    return watch.stagnating(6, 0.5);
  }


  template <int dim>
  bool
  NewtonMethod<dim>::iterate(const double   target,
                             ResidualNorms &norms,
                             StepResult    &result)
  {
    IterationAccess<dim> &analysis = this->analysis;
    const unsigned int    n_modes  = analysis.n_modes();

    if (!solve_correction(norms, result))
      {
        // A singular tangent: the active set is a mechanism (an interface
        // sliding along its whole length, say). An iteration with the
        // elastic factors keeps going, so that the state shows the
        // mechanism rather than stopping at the predictor.
        this->remember_increments();
        this->elastic_corrections();
        for (unsigned int m = 0; m < n_modes; ++m)
          analysis.get_step_increment()[m] += this->correction[m];
        norms = this->evaluate_residual(target, /*tangents=*/true);
        return true;
      }
    // Under work control the load factor is corrected with the
    // displacements, and scaled with them by the line search.
    double dlambda = 0;
    if (this->work_control && !correct_load_factor(dlambda))
      return false;
    this->remember_increments();

    // Backtracking on |r|_2: halve the step until the residual falls
    // (Armijo with 1e-4), at most four times.
    const double initial = norms.l2;
    double       scale   = 1;
    for (unsigned int trial = 0;; ++trial)
      {
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            ModeVector &increment = analysis.get_step_increment()[m];
            increment             = this->previous_increment[m];
            increment.add(scale, this->correction[m]);
          }
        this->load_factor_now = target + scale * dlambda;
        norms =
          this->evaluate_residual(this->load_factor_now, /*tangents=*/true);
        if (norms.l2 <= (1 - 1e-4 * scale) * initial || trial == 4)
          break;
        scale /= 2;
      }
    // An inexact correction that the line search could not make reduce
    // the residual may be no descent direction where the tangent is nearly
    // singular (a thin layer near its collapse): the rest of the attempt
    // solves its corrections exactly, as with Newton corrections =
    // factorised.
    if (norms.l2 > (1 - 1e-4 * scale) * initial)
      exact_corrections = true;
    return true;
  }


  template <int dim>
  void
  NewtonMethod<dim>::start_attempt()
  {
    last_l2      = 0;
    forcing_term = maximum_forcing_term;
    // The attempt whose failure would end the run solves its corrections
    // exactly throughout: a collapse is where Newton fails, not where an
    // inexact correction did. Under work control every correction is
    // exact: the load factor's comes from a factor of this tangent.
    exact_corrections = this->final_attempt || this->work_control;
  }


  template <int dim>
  double
  NewtonMethod<dim>::next_forcing_term(const ResidualNorms &norms)
  {
    // Eisenstat and Walker's second choice, gamma = 0.9, alpha = 2, with
    // their safeguard against a forcing term that falls too fast.
    constexpr double gamma = 0.9;
    if (last_l2 > 0)
      {
        const double ratio     = norms.l2 / last_l2;
        const double previous  = gamma * forcing_term * forcing_term;
        double       candidate = gamma * ratio * ratio;
        if (previous > 0.1)
          candidate = std::max(candidate, previous);
        forcing_term = std::min(candidate, maximum_forcing_term);
      }
    last_l2 = norms.l2;
    // No more than the convergence test needs: a linear residual a tenth
    // of the tolerance's (the test is on max |r|, which |r|_2 bounds).
    const double enough =
      norms.l2 > 0 ? 0.1 * this->parameters.tolerance * norms.forces / norms.l2
                   : maximum_forcing_term;
    return std::min(std::max(forcing_term, enough), maximum_forcing_term);
  }


  template <int dim>
  bool
  NewtonMethod<dim>::solve_correction(const ResidualNorms &norms,
                                      StepResult          &result)
  {
    IterationAccess<dim> &analysis = this->analysis;
    system->assemble([&analysis](const CellMatrixSink &add) {
      analysis.add_coupled_tangent(add);
    });
    const bool krylov = this->parameters.newton_corrections ==
                        SolverParameters::NewtonCorrections::krylov;
    // Every iteration of a Krylov attempt steps the forcing term on, the
    // ones that factorise too: it follows the residual's reduction.
    const double       tolerance = krylov ? next_forcing_term(norms) : 0;
    const unsigned int limit     = this->parameters.krylov_iterations;
    if (krylov && !refactorise && !exact_corrections)
      {
        const CoupledSystem::ModeSolve elastic = [&analysis](ModeVectors &v) {
          analysis.elastic_solve(v);
        };
        if (const std::optional<unsigned int> iterations =
              system->solve_iteratively(this->residual,
                                        this->correction,
                                        tolerance,
                                        limit,
                                        system->has_factor() ? nullptr
                                                             : &elastic))
          {
            result.krylov_iterations += *iterations;
            // A kept factor that needed more than half the limit is
            // replaced at the next iteration, before it wastes a solve.
            refactorise = 2 * *iterations > limit;
            return true;
          }
      }
    refactorise = false;
    ++result.factorisations;
    if (!system->factorise_assembled())
      return false;
    system->solve(this->residual, this->correction);
    return true;
  }


  template class NewtonMethod<2>;
  template class NewtonMethod<3>;
} // namespace thinlayer
