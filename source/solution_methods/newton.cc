#include <thinlayer/solution_methods/newton.h>
#include <thinlayer/solvers/singular_matrix.h>

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
    system = std::make_unique<CoupledSystem>(
      mode_constraints,
      analysis.get_dof_handler().n_dofs(),
      analysis.get_owned_per_rank(),
      analysis.all_laws_associated(),
      this->parameters.linear_solver == SolverParameters::LinearSolver::umfpack
        ? FactorisedStiffness::Method::umfpack
        : FactorisedStiffness::Method::cholmod);
    system->reinit(
      [&analysis](const DofSink &add) { analysis.add_coupled_sparsity(add); });
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

    ++result.factorisations;
    if (!factorise_tangent())
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
    // The coupled solve of the residuals, each condensed with its mode's
    // constraints.
    system->solve(this->residual, this->correction);
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
        norms = this->evaluate_residual(target, /*tangents=*/true);
        if (norms.l2 <= (1 - 1e-4 * scale) * initial || trial == 4)
          break;
        scale /= 2;
      }
    return true;
  }


  template <int dim>
  bool
  NewtonMethod<dim>::factorise_tangent()
  {
    IterationAccess<dim> &analysis = this->analysis;
    return system->factorise([&analysis](const CellMatrixSink &add) {
      analysis.add_coupled_tangent(add);
    });
  }


  template class NewtonMethod<2>;
  template class NewtonMethod<3>;
} // namespace thinlayer
