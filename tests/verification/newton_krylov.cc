// Truths checked: Newton's corrections solved by GMRES on a kept factor
// (Solver/Newton corrections = krylov, an inexact Newton method) bracket the
// same collapse of Prandtl's strip footing (prm/prandtl-strip-footing.prm
// on its 512-cell mesh, weightless Tresca soil, (2 + pi)c) as corrections
// solved by a factor of every tangent: both collapse loads within 1% of
// (2 + pi)c (the mesh's own error is below that), and within the collapse
// resolution (0.5%) of each other; the Krylov corrections need no more
// than one factorisation per two Newton iterations (every iteration
// factorises with the other), and did iterate (GMRES iterations > 0).
// Serially (CHOLMOD) and on two ranks (MUMPS's factor, GMRES on PETSc's
// vectors).

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/parallel_truths.h"
#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  struct Run
  {
    double       collapse;
    double       reference;
    unsigned int newton_iterations;
    unsigned int factorisations;
    unsigned int krylov_iterations;
  };

  Run
  run(const std::string &corrections)
  {
    const double collapse = run_results::run_prm(
      "prandtl-strip-footing.prm",
      {"Mesh/Geometry parameters=half_width=1, width=5, depth=3, "
       "n_footing=12, n_side=20, n_depth=16, growth=1.1",
       "Solver/Method=newton",
       "Solver/Convergence criterion=default",
       "Solver/Newton corrections=" + corrections,
       "Loading/Collapse resolution=0.005"});
    const auto number = [](const char *key) {
      return run_results::summary_number("results", key);
    };
    return {collapse,
            number("reference_load"),
            static_cast<unsigned int>(number("total_iterations")),
            static_cast<unsigned int>(number("factorisations")),
            static_cast<unsigned int>(number("krylov_iterations"))};
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  // Every rank reads the same summary; rank 0 prints.
  if (!truths::print_on_rank_zero())
    return 1;
  using truths::expect;
  const Run    factorised = run("factorised");
  const Run    krylov     = run("krylov");
  const double exact      = factorised.reference;
  // Errors as magnitudes: the sign of one below 0.005% is rounding's.
  std::printf("collapse load / c: factorised %.4f (error %.2f%%), krylov "
              "%.4f (error %.2f%%); exact %.4f\n",
              factorised.collapse,
              100 * std::abs(factorised.collapse / exact - 1),
              krylov.collapse,
              100 * std::abs(krylov.collapse / exact - 1),
              exact);
  expect(std::abs(exact - (2 + M_PI)) < 1e-9,
         "the file's reference is (2 + pi)c");
  expect(std::abs(factorised.collapse / exact - 1) < 0.01,
         "factorised corrections: collapse within 1% of (2 + pi)c");
  expect(std::abs(krylov.collapse / exact - 1) < 0.01,
         "Krylov corrections: collapse within 1% of (2 + pi)c");
  expect(std::abs(krylov.collapse - factorised.collapse) <= 0.005 * exact,
         "the two collapse loads within the resolution (0.5%)");
  expect(factorised.krylov_iterations == 0,
         "factorised corrections: no GMRES iteration");
  expect(krylov.krylov_iterations > 0, "Krylov corrections: GMRES iterated");
  expect(2 * krylov.factorisations <= krylov.newton_iterations,
         "Krylov corrections: at most one factorisation per two Newton "
         "iterations");
  return truths::conclude();
}
