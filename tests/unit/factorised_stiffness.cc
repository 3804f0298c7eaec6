// FactorisedStiffness (CHOLMOD and UMFPACK) on K = [[1, a], [b, a b + d]],
// whose pivots are 1 and d: its pivot ratio is d. Truths checked: with the
// elastic minimum (1e-12), a matrix with d = 1e-9 is factorised and solved
// (x = K^-1 b to the accuracy d leaves), one with d = 1e-14 is singular
// although its pivot is positive (round-off of a singular matrix comes out
// with either sign, by the processor's BLAS kernels), and a factorisation
// after a refused one works; without a minimum (Newton's tangent) d = 1e-14
// is factorised, and only the solvers' own verdicts remain: CHOLMOD refuses a
// negative pivot, UMFPACK an exactly zero one. The operations each solver
// counts (FactorisedStiffness::cost()): a substitution with the factor of a
// tridiagonal matrix of order n (no fill) costs a multiply-add (two
// operations) for each of the 2n - 1 entries of L in each of its two
// triangular solves, 4 (2n - 1); factorising a dense matrix of order n costs
// n^3 / 3 operations by Cholesky and 2 n^3 / 3 by LU to leading order
// (within 10% at n = 60), a tridiagonal one O(n).
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <thinlayer/solvers/factorised_stiffness.h>
#include <thinlayer/solvers/singular_matrix.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  using Method = FactorisedStiffness::Method;

  /// K with pivots 1 and @p d; symmetric for CHOLMOD (a = b = 1).
  struct TwoByTwo
  {
    TwoByTwo(const Method method, const double d)
    {
      pattern.reinit(2, 2, 2);
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          pattern.add(i, j);
      pattern.compress();
      matrix.reinit(pattern);
      const double a = 1, b = method == Method::cholmod ? 1 : 0.5;
      matrix.set(0, 0, 1);
      matrix.set(0, 1, a);
      matrix.set(1, 0, b);
      matrix.set(1, 1, a * b + d);
    }

    SparsityPattern      pattern;
    SparseMatrix<double> matrix;
  };

  /// Whether @p factorisation takes K(@p d).
  bool
  factorises(FactorisedStiffness &factorisation,
             const Method         method,
             const double         d)
  {
    const TwoByTwo k(method, d);
    try
      {
        factorisation.factorize(k.matrix);
        return true;
      }
    catch (const SingularMatrix &)
      {
        return false;
      }
  }

  /// The largest relative error of x solved from K x = K (1, 2).
  double
  solve_error(FactorisedStiffness &factorisation,
              const Method         method,
              const double         d)
  {
    const TwoByTwo k(method, d);
    Vector<double> exact(2), rhs(2);
    exact[0] = 1;
    exact[1] = 2;
    k.matrix.vmult(rhs, exact);
    std::vector<double> x(rhs.begin(), rhs.end());
    factorisation.factorize(k.matrix);
    factorisation.solve(make_array_view(x));
    return std::max(std::abs(x[0] - 1), std::abs(x[1] - 2) / 2);
  }
  /// The tridiagonal matrix (-1, 2, -1) of order @p n, or the dense
  /// n I + 1 (@p dense); both symmetric positive definite.
  struct Model
  {
    Model(const unsigned int n, const bool dense)
    {
      DynamicSparsityPattern dsp(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          if (dense || (i > j ? i - j : j - i) <= 1)
            dsp.add(i, j);
      pattern.copy_from(dsp);
      matrix.reinit(pattern);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          if (dense)
            matrix.set(i, j, (i == j ? n : 0) + 1.);
          else if (i == j)
            matrix.set(i, j, 2);
          else if ((i > j ? i - j : j - i) == 1)
            matrix.set(i, j, -1);
    }

    SparsityPattern      pattern;
    SparseMatrix<double> matrix;
  };


  void
  check_costs(const Method method)
  {
    FactorisedStiffness factorisation(method);
    expect(!factorisation.cost().known(), "no cost known before a factor");
    // Both alive at once: CHOLMOD's analysis is kept for the same
    // SparsityPattern object, which a temporary's address could mimic.
    constexpr unsigned int n = 60;
    const Model            tridiagonal_model(n, false), dense_model(n, true);
    factorisation.factorize(tridiagonal_model.matrix);
    const FactorCost tridiagonal = factorisation.cost();
    expect(tridiagonal.substitution == 4. * (2 * n - 1),
           "tridiagonal: a substitution costs 4 (2n - 1)");
    expect(tridiagonal.factorisation >= n &&
             tridiagonal.factorisation <= 10 * n,
           "tridiagonal: its factorisation costs between n and 10 n");
    factorisation.factorize(dense_model.matrix);
    const double leading =
      (method == Method::cholmod ? 1. : 2.) * n * n * n / 3;
    expect(std::abs(factorisation.cost().factorisation / leading - 1) < 0.1,
           method == Method::cholmod ? "dense: factorisation costs n^3 / 3"
                                     : "dense: factorisation costs 2 n^3 / 3");
  }
} // namespace


int
main()
{
  for (const Method method : {Method::cholmod, Method::umfpack})
    {
      const std::string name =
        method == Method::cholmod ? "CHOLMOD" : "UMFPACK";
      std::cout << "* " << name << '\n';
      {
        FactorisedStiffness elastic(method,
                                    FactorisedStiffness::elastic_pivot_ratio);
        // Solving with pivot ratio d loses digits as eps / d.
        expect(solve_error(elastic, method, 1e-9) < 1e-5,
               "elastic minimum: pivot ratio 1e-9 factorised and solved");
        expect(!factorises(elastic, method, 1e-14),
               "elastic minimum: pivot ratio 1e-14 (positive) singular");
        expect(!factorises(elastic, method, -1e-14),
               "elastic minimum: pivot ratio -1e-14 singular");
        expect(solve_error(elastic, method, 1e-9) < 1e-5,
               "after a refused matrix, the next factorised and solved");
      }
      {
        FactorisedStiffness tangent(method);
        expect(factorises(tangent, method, 1e-14),
               "no minimum: pivot ratio 1e-14 factorised");
        if (method == Method::cholmod)
          expect(!factorises(tangent, method, -1e-14),
                 "no minimum: a negative pivot singular");
        else
          expect(!factorises(tangent, method, 0),
                 "no minimum: a zero pivot singular");
      }
      check_costs(method);
    }
  return truths::conclude();
}
