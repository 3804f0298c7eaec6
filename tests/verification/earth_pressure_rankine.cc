// Truth checked: earth pressure with weight, from the at-rest state.
// prm/earth-pressure-rankine.prm: a smooth vertical wall of height H
// retaining a cohesionless Mohr-Coulomb backfill (unit weight gamma, no
// dilation) on a smooth base, which starts from the K0 procedure's
// at-rest stresses (K0 = 1 - sin(phi)) and is then moved away from the
// soil (active) or into it (passive). Rankine's coefficients are exact
// for a smooth wall: the wall's horizontal force per unit length levels
// off at K gamma H^2 / 2 with K_a = (1 - sin(phi)) / (1 + sin(phi)) and
// K_p = 1 / K_a, the pressure linear in depth, so the resultant acts at
// H / 3 above the base. For phi = 20, 30 and 40 degrees, active and
// passive: the plateau (summary.json's collapse_load under prescribed
// displacement) within 0.5% (the collapse resolution) of K, and the
// resultant's height, from the moment of the wall's reaction about the
// base, within 0.5% of H / 3. The same from gravity loading (elastic,
// then plastic as the wall moves): its at-rest ratio is that of an
// elastic oedometer, nu / (1 - nu), before the wall moves.

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// The plateau of the wall's reaction (its force, or with @p moment its
  /// moment about the base's corner) for friction angle @p phi.
  double
  plateau(const double       phi,
          const bool         passive,
          const bool         moment,
          const std::string &procedure = "K0 procedure")
  {
    const std::string              directory = "results";
    const std::vector<std::string> arguments = {
      std::string(SOURCE_DIR) + "/../../prm/earth-pressure-rankine.prm",
      "-s",
      "Mesh/Geometry parameters=width=2, height=1, nx=4, ny=4",
      "-s",
      "Material 1/Friction angle=" + std::to_string(phi),
      "-s",
      "Initial state/Procedure=" + procedure,
      "-s",
      std::string("Boundary 4/Displacement=") +
        (passive ? "1e-6; 0" : "-1e-6; 0"),
      "-s",
      std::string("Monitors/Load component=") + (moment ? "moment" : "x"),
      "-s",
      std::string("Monitors/Load scale=") + (moment ? "-2" : "2"),
      "-s",
      "Output/Directory=" + directory,
      "-s",
      "Output/Write VTU=false"};
    return run_results::run_and_read(arguments, "collapse_load", directory);
  }
} // namespace


int
main()
{
  using truths::expect;
  for (const double phi : {20., 30., 40.})
    for (const bool passive : {false, true})
      {
        const double s      = std::sin(phi * M_PI / 180);
        const double k      = passive ? (1 + s) / (1 - s) : (1 - s) / (1 + s);
        const double force  = plateau(phi, passive, false);
        const double height = plateau(phi, passive, true) / force; // of H = 1
        std::printf("phi = %.0f, %s: K = %.5f (Rankine %.5f, error "
                    "%+.3f%%), resultant at %.5f H above the base\n",
                    phi,
                    passive ? "passive" : "active",
                    force,
                    k,
                    100 * (force / k - 1),
                    height);
        expect(std::abs(force / k - 1) < 0.005, "the plateau is Rankine's K");
        expect(std::abs(3 * height - 1) < 0.005, "the resultant acts at H/3");
      }
  // From gravity loading: the wall's force at the end of the initial
  // state (history.csv's last step of that phase, summary.json's
  // initial_state_steps), then the active plateau.
  const double active           = plateau(30, false, false, "gravity loading");
  const run_results::Table rows = run_results::read_csv("results/history.csv");
  const double             initial_steps =
    run_results::summary_number("results", "initial_state_steps");
  double at_rest = std::numeric_limits<double>::quiet_NaN();
  for (const auto &row : rows)
    if (row.at("step") == initial_steps && row.at("accepted") == 1)
      at_rest = row.at("load");
  std::printf("gravity loading, phi = 30: at rest K = %.5f (nu / (1 - nu) = "
              "%.5f), active K = %.5f (Rankine %.5f)\n",
              at_rest,
              0.3 / 0.7,
              active,
              1. / 3);
  expect(std::abs(at_rest / (0.3 / 0.7) - 1) < 1e-6,
         "gravity loading leaves the oedometer's at-rest ratio");
  expect(std::abs(3 * active - 1) < 0.005,
         "the plateau from gravity loading is Rankine's K_a");
  return truths::conclude();
}
