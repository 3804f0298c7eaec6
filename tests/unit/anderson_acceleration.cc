// AndersonAcceleration on a linear fixed-point iteration x <- x + g(x),
// g(x) = M (b - A x) with M the inverse of A's diagonal (a Jacobi
// iteration). Truths checked: for a linear g, type-II Anderson with a depth
// of at least n is equivalent to GMRES (Walker and Ni 2011), so on an
// n x n system it reaches the solution in at most n + 1 updates (to
// round-off), where the plain iteration, converging at the spectral radius
// of I - M A, is still far from it; without history (the first update, and
// the first after reset()) it is the plain fixed-point step x + g exactly.
#include <deal.II/base/utilities.h>
#include <deal.II/lac/full_matrix.h>

#include <thinlayer/solvers/anderson_acceleration.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  constexpr unsigned int n = 4;

  /// A non-symmetric, diagonally dominant matrix whose Jacobi iteration
  /// converges slowly.
  FullMatrix<double>
  matrix()
  {
    const double       a[n][n] = {{4, -1.9, 0.5, 0.3},
                                  {-1.7, 4, -1.5, 0.2},
                                  {0.4, -1.8, 4, -1.6},
                                  {0.1, 0.6, -1.9, 4}};
    FullMatrix<double> A(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        A(i, j) = a[i][j];
    return A;
  }


  Vector<double>
  correction(const FullMatrix<double> &A,
             const Vector<double>     &b,
             const Vector<double>     &x)
  {
    Vector<double> g(n);
    A.vmult(g, x);
    g.sadd(-1, 1, b);
    for (unsigned int i = 0; i < n; ++i)
      g[i] /= A(i, i);
    return g;
  }


  std::string
  number(const double value)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3e", value);
    return text;
  }


  double
  error(const Vector<double> &x, const Vector<double> &exact)
  {
    Vector<double> e = x;
    e -= exact;
    return e.l2_norm() / exact.l2_norm();
  }
} // namespace


int
main()
{
  const FullMatrix<double> A = matrix();
  Vector<double>           exact(n), b(n);
  for (unsigned int i = 0; i < n; ++i)
    exact[i] = 1. + i;
  A.vmult(b, exact);

  std::cout << "* depth " << n << " on a " << n << " x " << n << " system\n";
  {
    AndersonAcceleration accelerated(n);
    Vector<double>       x(n), y(n);
    for (unsigned int k = 1; k <= n + 1; ++k)
      {
        accelerated.update(x, correction(A, b, x));
        y += correction(A, b, y); // the plain fixed-point step
        // Round-off is printed as such: its digits vary with the build.
        const double e = error(x, exact);
        std::printf("  update %u: error %s (plain %.3e)\n",
                    k,
                    e < 1e-12 ? "below 1e-12" : number(e).c_str(),
                    error(y, exact));
      }
    expect(error(x, exact) < 1e-10, "the solution after n + 1 updates");
    expect(error(y, exact) > 1e-3, "the plain iteration still far from it");

    accelerated.reset();
    Vector<double> z(n);
    accelerated.update(z, correction(A, b, z));
    Vector<double> w(n);
    w += correction(A, b, w);
    bool same = true;
    for (unsigned int i = 0; i < n; ++i)
      same = same && z[i] == w[i];
    expect(same, "after reset() the first update is the plain step");
  }

  return truths::conclude();
}
