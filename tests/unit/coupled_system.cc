// CoupledSystem's Krylov solve on a kept factor (Newton's corrections with
// Solver/Newton corrections = krylov), on a chain of n springs fixed at its
// first node: K = sum_e k_e g_e g_e^T with g_e = e_{e+1} - e_e. Softening
// s springs (spring 5 j to k / (1 + j), as yielding points soften Newton's
// tangent) changes K by a matrix of rank s, so the tangent preconditioned by
// the old factor is the identity plus rank s, and GMRES reaches any
// tolerance in at most s + 1 iterations (it minimises over a space that
// holds the exact solution by then; the chain being statically determinate,
// the s + 1 distinct eigenvalues are 1 and the ratios 1 / (1 + j), and it
// needs all s + 1). Truths: the direct solve meets K x = b to 1e-12; the
// Krylov solve of the softened tangent on the kept factor meets its
// tolerance (|b - K' x| <= 1e-10 |b|, K' x computed here), within s + 1
// iterations, for s = 1, 3 and 6; with a limit of one iteration (s > 1) it
// reports that it did not converge; the elastic preconditioner (a caller's
// solve) does the same as the kept factor of the same matrix; a zero right-hand
// side gives a zero correction in no iteration; and factorising a singular
// tangent leaves no factor held.
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <thinlayer/analysis/coupled_system.h>
#include <thinlayer/solvers/factorised_stiffness.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  constexpr unsigned int n = 40;

  /// The springs' stiffnesses: 1 + e / n, the first @p softened of the
  /// springs 5 j (j = 1, 2, ...) divided by 1 + j (all of them zero:
  /// @p zero).
  std::vector<double>
  stiffnesses(const unsigned int softened, const bool zero = false)
  {
    std::vector<double> k(n - 1);
    for (unsigned int e = 0; e + 1 < n; ++e)
      k[e] = zero ? 0. : 1 + double(e) / n;
    for (unsigned int j = 1; j <= softened; ++j)
      k[5 * j] /= 1 + j;
    return k;
  }

  /// Hands spring e's matrix k_e [[1, -1], [-1, 1]] on DoFs e, e + 1.
  std::function<void(const CellMatrixSink &)>
  springs(const std::vector<double> &k)
  {
    return [k](const CellMatrixSink &add) {
      for (unsigned int e = 0; e < k.size(); ++e)
        {
          FullMatrix<double> m(2, 2);
          m(0, 0) = m(1, 1) = k[e];
          m(0, 1) = m(1, 0) = -k[e];
          add({e, e + 1}, m);
        }
    };
  }

  /// |b - K x|_2 / |b|_2 for the chain @p k fixed at node 0.
  double
  relative_residual(const std::vector<double> &k,
                    const ModeVector          &x,
                    const ModeVector          &b)
  {
    ModeVector r = b;
    for (unsigned int e = 0; e < k.size(); ++e)
      {
        const double f = k[e] * (x[e + 1] - x[e]);
        r[e] += f;
        r[e + 1] -= f;
      }
    r[0] = 0; // the fixed DoF
    return r.l2_norm() / b.l2_norm();
  }
} // namespace


int
main()
{
  AffineConstraints<double> constraints;
  constraints.add_line(0);
  constraints.close();
  CoupledSystem system({&constraints},
                       n,
                       {},
                       /*symmetric=*/true,
                       FactorisedStiffness::Method::cholmod);
  system.reinit([](const DofSink &add) {
    for (unsigned int e = 0; e + 1 < n; ++e)
      add({e, e + 1});
  });

  ModeVectors b(1), x(1);
  b[0].reinit(n);
  x[0].reinit(n);
  for (unsigned int i = 1; i < n; ++i)
    b[0][i] = std::sin(0.3 * i) + 0.1;

  const std::vector<double> elastic = stiffnesses(0);
  system.assemble(springs(elastic));
  expect(system.factorise_assembled() && system.has_factor(),
         "the elastic chain factorised");
  system.solve(b, x);
  expect(relative_residual(elastic, x[0], b[0]) < 1e-12,
         "direct solve: |b - K x| < 1e-12 |b|");

  for (const unsigned int s : {1u, 3u, 6u})
    {
      const std::vector<double> softened = stiffnesses(s);
      system.assemble(springs(softened));
      const std::optional<unsigned int> iterations =
        system.solve_iteratively(b, x, 1e-10, 50);
      const bool converged = iterations.has_value();
      std::cout << "  " << s << " springs softened: "
                << (converged ? std::to_string(*iterations) : "no")
                << " iterations\n";
      expect(converged && *iterations <= s + 1,
             "kept factor, rank-" + std::to_string(s) +
               " change: converged within " + std::to_string(s + 1) +
               " iterations");
      expect(converged && relative_residual(softened, x[0], b[0]) <= 1e-10,
             "kept factor: |b - K' x| <= 1e-10 |b|");
      if (s > 1)
        expect(!system.solve_iteratively(b, x, 1e-10, 1),
               "a limit of one iteration: reported as not converged");
    }

  // The elastic preconditioner: the caller's solve with the elastic factor.
  {
    FactorisedStiffness            factor(FactorisedStiffness::Method::cholmod);
    const std::vector<double>      softened      = stiffnesses(3);
    const CoupledSystem::ModeSolve elastic_solve = [&](ModeVectors &v) {
      factor.solve(make_array_view(v[0].begin(), v[0].end()));
    };
    system.assemble(springs(elastic));
    system.factorise_assembled();
    // The same matrix into a factor of the caller's own.
    SparsityPattern pattern(n, n, 3);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
        pattern.add(i, j);
    pattern.compress();
    SparseMatrix<double> matrix(pattern);
    springs(elastic)([&](const std::vector<types::global_dof_index> &dofs,
                         const FullMatrix<double>                   &m) {
      constraints.distribute_local_to_global(m, dofs, matrix);
    });
    factor.factorize(matrix);
    system.assemble(springs(softened));
    const std::optional<unsigned int> kept =
      system.solve_iteratively(b, x, 1e-10, 50);
    const std::optional<unsigned int> by_caller =
      system.solve_iteratively(b, x, 1e-10, 50, &elastic_solve);
    expect(kept && by_caller && *kept == *by_caller &&
             relative_residual(softened, x[0], b[0]) <= 1e-10,
           "the elastic preconditioner: as many iterations as the kept "
           "factor of the same matrix, and the tolerance met");
  }

  ModeVectors zero(1);
  zero[0].reinit(n);
  const std::optional<unsigned int> none =
    system.solve_iteratively(zero, x, 1e-10, 50);
  expect(none && *none == 0 && x[0].linfty_norm() == 0,
         "a zero residual: a zero correction in no iteration");

  system.assemble(springs(stiffnesses(0, /*zero=*/true)));
  expect(!system.factorise_assembled() && !system.has_factor(),
         "a singular tangent: refused, and no factor held");
  return truths::conclude();
}
