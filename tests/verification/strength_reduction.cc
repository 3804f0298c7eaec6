// Truth checked: the safety factor by strength reduction (Strength
// reduction: c and tan(phi) divided by F after gravity loading).
//  - A vertical cut in Tresca clay (prm/vertical-cut.prm, 256 cells)
//    loaded by its weight to gamma H / c = 2, then its c reduced: the cut
//    fails when c / F reaches gamma H / N, N the critical gamma H_c / c of
//    the same mesh found by raising the weight (gravity loading to
//    collapse), so F = N / 2; both are bracketed to 0.5%, so they agree
//    within 1%.
//  - A slab on a thin cohesionless seam parallel to a base inclined at
//    beta = 20 degrees (prm/inclined-seam-strength-reduction.prm, phi =
//    30 degrees, associated flow): by statics the slab slides when
//    tan(phi) / F = tan(beta), F = 1.5863; the finite elements find it
//    from below (the seam's ends carry less than its limit), within 1.5%
//    on the file's mesh and closer on one with half the elements' size and
//    half the seam's thickness.
//  - The same seam as zero-thickness interface elements (a Coulomb
//    interface, prm/inclined-seam-zero-thickness-strength-reduction.prm):
//    its tractions are admissible, so by statics F cannot exceed
//    tan(phi) / tan(beta); it lies below it, within 1%.

#include <thinlayer/base/text_format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// The collapse load of @p prm with the overrides @p settings, and the
  /// phase its summary is of.
  double
  collapse(const std::string              &prm,
           const std::vector<std::string> &settings,
           std::string                    &phase)
  {
    std::vector<std::string> arguments = {std::string(SOURCE_DIR) +
                                            "/../../prm/" + prm,
                                          "-s",
                                          "Output/Directory=results",
                                          "-s",
                                          "Output/Write VTU=false"};
    for (const std::string &s : settings)
      {
        arguments.push_back("-s");
        arguments.push_back(s);
      }
    const double  load = run_results::run_and_read(arguments, "collapse_load");
    std::ifstream json("results/summary.json");
    std::string   line;
    phase.clear();
    while (std::getline(json, line))
      if (line.find("\"phase\"") != std::string::npos)
        phase =
          line.substr(line.find(':') + 3, line.rfind('"') - line.find(':') - 3);
    return load;
  }
} // namespace


int
main()
{
  using truths::expect;
  std::string  phase;
  const double critical = collapse("vertical-cut.prm", {}, phase);
  const double factor =
    collapse("vertical-cut.prm",
             {"Material 1/Unit weight=2",
              "Initial state/Procedure=gravity loading",
              "Strength reduction/Materials=1",
              "Strength reduction/Factor increments=0.5, 0.25, 0.25, 0.5"},
             phase);
  std::printf("vertical cut: gamma H_c / c = %.4f by its weight; at gamma H "
              "/ c = 2, F = %.4f by strength reduction (%s), N / 2 = %.4f, "
              "%+.2f%%\n",
              critical,
              factor,
              phase.c_str(),
              critical / 2,
              100 * (2 * factor / critical - 1));
  expect(phase == "strength reduction",
         "the safety factor is the last phase's");
  expect(std::abs(2 * factor / critical - 1) < 0.01,
         "strength reduction and the weight's collapse agree");

  const double exact = std::tan(M_PI / 6) / std::tan(M_PI / 9);
  const double coarse =
    collapse("inclined-seam-strength-reduction.prm", {}, phase);
  const double fine = collapse(
    "inclined-seam-strength-reduction.prm",
    {"Mesh/Geometry parameters=length=10, slab=1, seam=0.025, angle=20, "
     "n_along=80, n_slab=8"},
    phase);
  std::printf("inclined seam: F = %.4f, then %.4f with half the elements "
              "and the seam (tan(phi) / tan(beta) = %.4f: %+.2f%%, "
              "%+.2f%%)\n",
              coarse,
              fine,
              exact,
              100 * (coarse / exact - 1),
              100 * (fine / exact - 1));
  expect(coarse < exact && std::abs(coarse / exact - 1) < 0.015,
         "the seam slides just below tan(phi) / tan(beta)");
  expect(fine > coarse && fine < exact, "and closer to it when refined");

  const double interface =
    collapse("inclined-seam-zero-thickness-strength-reduction.prm", {}, phase);
  std::printf("inclined seam as interface elements: F = %.4f (%+.2f%%)\n",
              interface,
              100 * (interface / exact - 1));
  expect(interface <= exact && interface / exact - 1 > -0.01,
         "the interface slides just below tan(phi) / tan(beta)");
  // One figure, one meaning: the summary names the safety factor, and the
  // bracket the reason states is in F (not in F - 1).
  const double safety = run_results::summary_number("results", "safety_factor");
  const double low    = run_results::summary_number("results", "low");
  const double high   = run_results::summary_number("results", "high");
  const std::string reason = run_results::summary_text("results", "reason");
  std::printf("  its summary: safety_factor %.4f, the bracket %.6g - %.6g\n",
              safety,
              low,
              high);
  expect(safety == interface, "safety_factor is the phase's collapse load F");
  expect(low <= safety && safety < high && low > 1,
         "the bracket holds F and is stated in F");
  expect(reason.find("the safety factor lies between " +
                     thinlayer::text_format::printf("%.6g", low)) !=
           std::string::npos,
         "the reason states the same bracket");
  return truths::conclude();
}
