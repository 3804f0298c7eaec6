// Truth checked: a plateau of states that drifted outside the yield surface
// is no collapse load. The active thrust on a rough wall
// (prm/earth-pressure-wall-friction-zero-thickness.prm, delta = 20) by the
// paper's viscoplastic method with the displacement test at TOL = 1e-3:
// near the ground the at-rest stresses of the cohesionless backfill are
// small, the viscoplastic strain increments overshoot its apex, and the
// accepted states lie outside the yield surface. Their load levels off far
// outside the bracket [K_C, K_a] = [0.2794, 0.3333] that Coulomb's
// mechanism and Rankine's stress field put on the exact thrust (the bound
// theorems; tests/verification/wall_friction), so it is not the limit:
// the run must flag the drift and claim no plateau (no collapse load). The
// default method on the same scene claims one, inside [0.25, K_a] (a
// displacement method's thrust lies below the exact one; 0.2629 on this mesh).

#include <cmath>
#include <cstdio>
#include <string>

#include "../common/run_results.h"
#include "../common/truths.h"

int
main()
{
  using truths::expect;
  const double rankine = 1. / 3;

  const double paper =
    run_results::run_prm("earth-pressure-wall-friction-zero-thickness.prm",
                         {"Solver/Method=viscoplastic",
                          "Solver/Convergence criterion=displacements",
                          "Solver/Tolerance=1e-3"});
  const double drift =
    run_results::summary_number("results", "steps_with_drift");
  const double last =
    run_results::summary_number("results", "last_converged_load");
  const std::string reason = run_results::summary_text("results", "reason");
  // Coulomb's active thrust with wall friction, as the file's
  // Reference/Analytic load states it.
  const double coulomb =
    run_results::summary_number("results", "reference_load");
  std::printf("paper's method: %g steps with drift, last converged load "
              "%.4g, collapse load %g\n",
              drift,
              last,
              paper);
  expect(drift > 0, "the accepted states drift outside the yield surface");
  expect(last < coulomb || last > rankine,
         "their load lies outside the bracket on the exact thrust");
  expect(std::isnan(paper) &&
           reason.find("no plateau is claimed") != std::string::npos,
         "no plateau is claimed, and the reason says why");

  const double ours =
    run_results::run_prm("earth-pressure-wall-friction-zero-thickness.prm");
  std::printf("default method: %g steps with drift, collapse load %.4f\n",
              run_results::summary_number("results", "steps_with_drift"),
              ours);
  expect(ours >= 0.25 && ours <= rankine,
         "the default method claims its plateau, below Rankine's");
  return truths::conclude();
}
