#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <thinlayer/solution_methods/newton.h>
#include <thinlayer/solvers/singular_matrix.h>

namespace thinlayer
{
  template <int dim>
  void
  NewtonMethod<dim>::initialize()
  {
    ReturnMappingMethod<dim>::initialize();
    Analysis<dim>     &analysis = this->analysis;
    const unsigned int n        = analysis.get_dof_handler().n_dofs();
    const unsigned int n_modes  = analysis.n_modes();

    constraints.clear();
    for (unsigned int m = 0; m < n_modes; ++m)
      {
        AffineConstraints<double> shifted;
        shifted.copy_from(analysis.mode_system(m).constraints);
        shifted.shift(m * n);
        constraints.merge(shifted);
      }
    constraints.close();

    DynamicSparsityPattern dsp(n_modes * n);
    analysis.add_coupled_sparsity(dsp, constraints);
    sparsity.copy_from(dsp);
    tangent.reinit(sparsity);
    coupled_vector.reinit(n_modes * n);

    // A non-associated flow rule makes the tangent unsymmetric.
    factorisation = std::make_unique<FactorisedStiffness>(
      analysis.all_laws_associated() &&
          this->parameters.linear_solver ==
            SolverParameters::LinearSolver::cholmod
        ? FactorisedStiffness::Method::cholmod
        : FactorisedStiffness::Method::umfpack);
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
  NewtonMethod<dim>::iterate(const double   target,
                             ResidualNorms &norms,
                             StepResult    &result)
  {
    Analysis<dim>     &analysis = this->analysis;
    const unsigned int n        = analysis.get_dof_handler().n_dofs();
    const unsigned int n_modes  = analysis.n_modes();

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
          analysis.step_increment()[m] += this->correction[m];
        norms = this->evaluate_residual(target, /*tangents=*/true);
        return true;
      }
    // The coupled solve: the residuals (each condensed with its mode's
    // constraints) one after the other.
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int i = 0; i < n; ++i)
        coupled_vector[m * n + i] = this->residual[m][i];
    factorisation->solve(coupled_vector);
    constraints.distribute(coupled_vector);
    for (unsigned int m = 0; m < n_modes; ++m)
      for (unsigned int i = 0; i < n; ++i)
        this->correction[m][i] = coupled_vector[m * n + i];
    this->remember_increments();

    // Backtracking on |r|_2: halve the step until the residual falls
    // (Armijo with 1e-4), at most four times.
    const double initial = norms.l2;
    double       scale   = 1;
    for (unsigned int trial = 0;; ++trial)
      {
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            Vector<double> &increment = analysis.step_increment()[m];
            increment                 = this->previous_increment[m];
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
    tangent = 0;
    this->analysis.add_coupled_tangent(tangent, constraints);
    try
      {
        factorisation->factorize(tangent);
      }
    catch (const SingularMatrix &)
      {
        return false; // a mechanism has formed
      }
    return true;
  }


  template class NewtonMethod<2>;
} // namespace thinlayer
