// Truth checked: a rigid pile pushed down through cohesionless
// Mohr-Coulomb soil with weight, by Fourier harmonic 0, slides on
// zero-thickness Coulomb interface elements along its shaft
// (prm/pile-shaft-axial-zero-thickness.prm: delta = 20 degrees, K0 = 0.6,
// R = 0.5, L = 10). At the end of the loading, its load levelled off:
//  - every point of the shaft slides: tau = sigma_n tan(delta) (Coulomb),
//    to 1e-6 of the largest normal traction; so the shaft resistance is
//    exactly tan(delta) times the integral of the normal traction the soil
//    keeps on the shaft;
//  - statics: the pile's load equals the integral of 2 pi r tau over the
//    interface (the shaft, and below the toe the soft column that carries
//    the toe, which drags the soil there), integrated with the elements'
//    own Gauss points, at which the raw profile is written, within 0.5% (the
//    column's base carries the rest);
//  - the Gauss points integrate the classical estimate, the beta method's
//    normal traction K0 gamma z, exactly (1e-6).
// How far the shaft resistance lies from the beta method's estimate is
// measured, not asserted: the normal traction rises above K0 gamma z near
// the ground and falls below it near the toe as the pile is loaded (+3.8%
// here; the report's section on the pile).
//
// The same pile on a thin frictional layer of elements along its shaft
// (prm/pile-shaft-axial.prm: phi_s = 20, no dilation, t = R / 10, K0 = 1)
// levels off, and at the end:
//  - every point of the layer yields, and none lies beyond Coulomb's line
//    of the layer's material, |tau| <= sigma_n tan(phi_s) (1e-9): a
//    cohesionless Mohr-Coulomb stress puts no traction beyond it on any
//    plane;
//  - statics: the pile's load equals the integral of 2 pi r tau over the
//    layer's midline (its raw profile, two Gauss points per cell), within 0.5%
//    (the soft column under the toe carries the rest).
// Measured, not asserted: the load against the beta method with Davis's
// (1968) tan(delta) = sin(phi_s) (+5.0%), and tau / sigma_n along the layer
// against sin(phi_s).
// Every truth here is of the points' own states: the test reads the raw
// profiles (Output/Gauss-point profiles), not the recovered ones.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// The newest profile results/@p prefix*.csv, sorted from the bottom up.
  run_results::Table
  last_profile(const std::string &prefix)
  {
    run_results::Table profile =
      run_results::read_csv(run_results::newest_csv("results", prefix));
    std::sort(profile.begin(), profile.end(), [](const auto &a, const auto &b) {
      return a.at("y") < b.at("y");
    });
    return profile;
  }


  /// The pile on a thin frictional layer: its truths.
  void
  thin_layer()
  {
    using truths::expect;
    const double R = 0.5, L = 10, K = 1, gamma = 1;
    const double phi_s = 20 * M_PI / 180;
    const double beta  = M_PI * R * L * L * K * gamma * std::sin(phi_s);

    const double load =
      run_results::run_prm("pile-shaft-axial.prm",
                           {"Output/Gauss-point profiles=true"});
    const std::string outcome = run_results::summary_text("results", "outcome");
    std::printf("thin layer: outcome %s, load / beta-method estimate %.4f\n",
                outcome.c_str(),
                load);
    expect(outcome == "completed" && std::isfinite(load),
           "the pile's load levels off");

    const run_results::Table profile = last_profile("layer-2-gauss-");
    expect(profile.size() % 2 == 0, "two Gauss points per cell side");
    double       shear = 0, beyond = 0, largest = 0, low = 1, high = 0;
    unsigned int elastic = 0;
    for (unsigned int k = 0; k + 1 < profile.size(); k += 2)
      {
        // Gauss abscissae -+1/sqrt(3) of the side's half length h / 2,
        // weights 1.
        const double h =
          (profile[k + 1].at("y") - profile[k].at("y")) * std::sqrt(3.);
        for (unsigned int q = 0; q < 2; ++q)
          {
            const auto  &p     = profile[k + q];
            const double sigma = -p.at("normal_traction");
            const double tau   = std::abs(p.at("shear_traction"));
            shear += 2 * M_PI * p.at("x") * h / 2 * tau;
            beyond  = std::max(beyond, tau - sigma * std::tan(phi_s));
            largest = std::max(largest, sigma);
            elastic += p.at("plastic") == 0;
            low  = std::min(low, tau / sigma);
            high = std::max(high, tau / sigma);
          }
      }
    const double last_load =
      run_results::summary_number("results", "last_converged_load");
    std::printf("  at the end: load %.4f, the layer's shear %.4f (divided by "
                "the estimate); tau / sigma_n from %.4f to %.4f, sin(phi_s) "
                "%.4f\n",
                last_load,
                shear / beta,
                low,
                high,
                std::sin(phi_s));
    expect(elastic == 0, "every point of the layer yields");
    expect(beyond <= 1e-9 * largest,
           "no point lies beyond tau = sigma_n tan(phi_s)");
    expect(std::abs(last_load / (shear / beta) - 1) < 0.005,
           "the pile's load is the layer's shear (statics)");
  }
} // namespace


int
main()
{
  using truths::expect;
  const double R = 0.5, t = 0.05, L = 10, K0 = 0.6, gamma = 1;
  const double tan_delta = std::tan(20 * M_PI / 180);
  const double beta      = M_PI * (R + t) * L * L * K0 * gamma * tan_delta;

  const double load =
    run_results::run_prm("pile-shaft-axial-zero-thickness.prm",
                         {"Output/Gauss-point profiles=true"});
  const std::string outcome = run_results::summary_text("results", "outcome");
  std::printf("outcome %s, load / beta-method estimate %.4f\n",
              outcome.c_str(),
              load);
  expect(outcome == "completed" && std::isfinite(load),
         "the pile's load levels off");

  // The profile of the last step, three Gauss points per cell side, from
  // the bottom up.
  const run_results::Table profile = last_profile("interface-6-gauss-");
  expect(profile.size() % 3 == 0, "three Gauss points per cell side");

  double shaft = 0, below = 0, normal = 0, at_rest = 0, worst_slip = 0,
         largest = 0;
  for (unsigned int k = 0; k + 2 < profile.size(); k += 3)
    {
      // Gauss abscissae -+sqrt(3/5) of the side's half length h / 2.
      const double h =
        (profile[k + 2].at("y") - profile[k].at("y")) / std::sqrt(3. / 5.);
      const double weights[] = {5. / 18, 8. / 18, 5. / 18};
      for (unsigned int q = 0; q < 3; ++q)
        {
          const auto  &p     = profile[k + q];
          const double depth = -p.at("y");
          const double sigma = -p.at("normal_traction");
          const double w     = 2 * M_PI * p.at("x") * h * weights[q];
          if (depth > L)
            {
              below += w * p.at("shear_traction");
              continue;
            }
          shaft += w * p.at("shear_traction");
          normal += w * sigma;
          at_rest += w * K0 * gamma * depth;
          worst_slip = std::max(worst_slip,
                                std::abs(std::abs(p.at("shear_traction")) -
                                         sigma * tan_delta));
          largest    = std::max(largest, sigma);
        }
    }
  const double last_load =
    run_results::summary_number("results", "last_converged_load");
  std::printf("at the end: load %.4f, the shaft's shear %.4f, the soil's "
              "below the toe %.4f; tan(delta) times the integral of sigma_n "
              "%.4f, of K0 gamma z %.4f (all divided by the beta method's "
              "estimate)\n",
              last_load,
              std::abs(shaft) / beta,
              std::abs(below) / beta,
              normal * tan_delta / beta,
              at_rest * tan_delta / beta);
  expect(worst_slip < 1e-6 * largest,
         "every point of the shaft slides at tau = sigma_n tan(delta)");
  expect(std::abs(last_load / (std::abs(shaft + below) / beta) - 1) < 0.005,
         "the pile's load is the interface's shear (statics)");
  expect(std::abs(at_rest * tan_delta / beta - 1) < 1e-6,
         "the Gauss points integrate K0 gamma z exactly");

  thin_layer();
  return truths::conclude();
}
