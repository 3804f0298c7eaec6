// Truths checked on the tractions interface elements write at collapse,
// recovered at the nodes from the interface's nodal forces
// (TractionRecovery; the raw values at the Gauss points oscillate once the
// soil flows):
// - a smooth rigid strip footing on weightless Tresca soil
//   (prm/strip-footing-rigid-smooth-zero-thickness.prm: half-width B = 1,
//   8 cells under the half footing, interface elements of adhesion 1e-3 c)
//   pushed down to collapse: the contact pressure is uniform at Prandtl's
//   (2 + pi) c (Prandtl 1920, Hill 1950), every sample beyond the first
//   cell from the footing's edge within 5%, and the collapse load itself
//   within the 5% the pressure is held to;
// - Griffiths' Case 2 on interface elements
//   (prm/case2-strip-footing-zero-thickness.prm: a strip footing pushed
//   sideways on Tresca elements of adhesion C_w = 1) at sliding: the shear
//   traction equals C_w within 2% along the footing, every sample beyond
//   the first cell from either end.
// - the smooth pile section on interface elements refined adaptively
//   (prm/circular-inclusion-zero-thickness-adaptive.prm): at the last
//   cycle, whose contact has sides of different lengths (hanging vertices
//   along it, where the recovery's nodes are the fine sides' alone), the
//   normal traction stays within 25 c and no two neighbouring samples
//   differ by more than 3 c, as on the uniform mesh.
// The 3D sliding block's truth (the shear traction uniform at c within 2%)
// is in unit/interface_elements_3d, the pile section's (smooth and within
// 25 c) in verification/circular_inclusion.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// The profile @p directory/@p prefix NNNN.csv of the last converged
  /// and accepted step (history.csv), in order along its run.
  run_results::Table
  last_profile(const std::string &prefix,
               const std::string &directory = "results")
  {
    unsigned int step = 0;
    for (const auto &row : run_results::read_csv(directory + "/history.csv"))
      if (row.at("converged") == 1 && row.at("accepted") == 1)
        step = static_cast<unsigned int>(row.at("step"));
    char number[16];
    std::snprintf(number, sizeof(number), "%04u.csv", step);
    run_results::Table profile =
      run_results::read_csv(directory + "/" + prefix + number);
    std::sort(profile.begin(), profile.end(), [](const auto &a, const auto &b) {
      return a.at("arc_length") < b.at("arc_length");
    });
    return profile;
  }
} // namespace


int
main()
{
  using truths::expect;
  const double prandtl = 2 + M_PI;

  {
    const double load =
      run_results::run_prm("strip-footing-rigid-smooth-zero-thickness.prm");
    const std::string outcome = run_results::summary_text("results", "outcome");
    std::printf("smooth rigid strip footing: outcome %s, collapse load %.3f "
                "(2 + pi = %.3f)\n",
                outcome.c_str(),
                load,
                prandtl);
    expect(outcome == "completed" && std::abs(load / prandtl - 1) < 0.05,
           "the footing collapses at (2 + pi) c B within 5%");
    // Three Gauss points per side, from the centreline to the edge: the
    // last three are the first cell from the edge.
    const run_results::Table profile = last_profile("interface-5-");
    expect(profile.size() == 3 * 8, "three samples on each of 8 sides");
    double worst = profile.size() > 3 ? 0 : 1;
    for (unsigned int k = 0; k + 3 < profile.size(); ++k)
      worst =
        std::max(worst,
                 std::abs(-profile[k].at("normal_traction") / prandtl - 1));
    std::printf("  contact pressure beyond the first cell from the edge: "
                "at most %.1f%% from (2 + pi) c\n",
                100 * worst);
    expect(worst < 0.05, "uniform at (2 + pi) c within 5%");
  }

  {
    const double load =
      run_results::run_prm("case2-strip-footing-zero-thickness.prm");
    const std::string outcome = run_results::summary_text("results", "outcome");
    std::printf("Case 2 on interface elements: outcome %s, collapse load "
                "%.4f L C_w\n",
                outcome.c_str(),
                load);
    const run_results::Table profile = last_profile("interface-5-");
    expect(outcome == "collapse" && profile.size() == 3 * 8,
           "it slides; three samples on each of 8 sides at its last "
           "converged step");
    double worst = profile.size() > 6 ? 0 : 1;
    for (unsigned int k = 3; k + 3 < profile.size(); ++k)
      worst = std::max(worst,
                       std::abs(std::abs(profile[k].at("shear_traction")) - 1));
    std::printf("  shear traction beyond the first cell from either end: at "
                "most %.2f%% from C_w\n",
                100 * worst);
    expect(worst < 0.02, "equal to C_w within 2%");
  }
  {
    run_results::run_prm("circular-inclusion-zero-thickness-adaptive.prm");
    unsigned int cycles = 0;
    while (std::filesystem::exists("results/cycle-" + std::to_string(cycles)))
      ++cycles;
    const run_results::Table profile =
      cycles > 0 ? last_profile("interface-4-",
                                "results/cycle-" + std::to_string(cycles - 1))
                 : run_results::Table();
    // Each side's length from its three Gauss points' arc lengths.
    double shortest = 1e300, longest = 0;
    for (unsigned int k = 0; k + 2 < profile.size(); k += 3)
      {
        const double side =
          (profile[k + 2].at("arc_length") - profile[k].at("arc_length")) /
          std::sqrt(3. / 5.);
        shortest = std::min(shortest, side);
        longest  = std::max(longest, side);
      }
    const auto [largest, jump] =
      run_results::spread(profile, "normal_traction");
    std::printf("the pile section refined adaptively, last of %u cycles:\n",
                cycles);
    expect(cycles > 1 && profile.size() % 3 == 0 && longest >= 1.9 * shortest,
           "its contact's sides differ in length (hanging vertices)");
    std::printf("  |sigma_n| at most %.1f c, neighbours differ by at most "
                "%.1f c\n",
                largest,
                jump);
    expect(largest < 25 && jump < 3,
           "the normal traction within 25 c, no jump between neighbours "
           "above 3 c");
  }
  return truths::conclude();
}
