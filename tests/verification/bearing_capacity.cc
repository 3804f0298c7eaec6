// Truth checked: bearing capacity factors of a smooth rigid strip footing
// on weightless Mohr-Coulomb soil (associated flow), against the exact
// solutions of Prandtl (1920) and Reissner (1924),
//   N_q = exp(pi tan(phi)) tan^2(45 + phi/2),  N_c = (N_q - 1) cot(phi),
// for phi = 20 and 30 degrees (prm/strip-footing-bearing-capacity.prm):
//  - N_q: a surcharge q = 1 beside the footing (Initial state/Surcharge),
//    the soil starting from the K0 procedure's stresses, the footing
//    pushed down: its pressure levels off at q N_q;
//  - N_c: c = 1, no surcharge, from a stress-free start: c N_c.
// A displacement method collapses above the exact load: each plateau lies
// above its factor and within 3% of it (measured +1.2% to +1.6% on this
// mesh).

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  double
  plateau(const double phi, const bool surcharge)
  {
    std::vector<std::string> arguments = {
      std::string(SOURCE_DIR) + "/../../prm/strip-footing-bearing-capacity.prm",
      "-s",
      "Material 1/Friction angle=" + std::to_string(phi),
      "-s",
      "Material 1/Dilation angle=" + std::to_string(phi),
      "-s",
      "Output/Directory=results",
      "-s",
      "Output/Write VTU=false"};
    if (!surcharge)
      for (const std::string s : {"Initial state/Procedure=none",
                                  "Initial state/Surcharge=0",
                                  "Material 1/Cohesion=1"})
        {
          arguments.push_back("-s");
          arguments.push_back(s);
        }
    return run_results::run_and_read(arguments, "collapse_load");
  }
} // namespace


int
main()
{
  using truths::expect;
  for (const double phi : {20., 30.})
    {
      const double t = std::tan(phi * M_PI / 180);
      const double nq =
        std::exp(M_PI * t) * std::pow(std::tan(M_PI / 4 + phi * M_PI / 360), 2);
      const double nc = (nq - 1) / t;
      for (const bool surcharge : {true, false})
        {
          const double exact = surcharge ? nq : nc;
          const double found = plateau(phi, surcharge);
          std::printf("phi = %.0f: %s = %.4f (exact %.4f, %+.2f%%)\n",
                      phi,
                      surcharge ? "N_q" : "N_c",
                      found,
                      exact,
                      100 * (found / exact - 1));
          expect(found > exact && found / exact - 1 < 0.03,
                 "above the exact factor, within 3%");
        }
    }
  return truths::conclude();
}
