// Truth checked: a rigid circular pile section moving laterally through
// weightless Tresca soil (plane strain, far from the ground), its contact a
// thin Tresca layer of strength alpha c (prm/circular-inclusion.prm,
// t = R / 50) or zero-thickness Tresca interface elements of adhesion
// alpha c (prm/circular-inclusion-zero-thickness.prm), for a smooth
// (alpha = 0.01) and a rough (alpha = 1) pile, against the exact limiting
// pressure of Randolph and Houlsby (1984, Geotechnique 34(4) 613-623; their
// lower bound, matched by the upper bound of Martin and Randolph 2006,
// Geotechnique 56(2) 141-145):
//   P / (c D) = pi + 2 Delta + 2 cos(Delta) + 4 (cos(Delta / 2) +
//               sin(Delta / 2)), sin(Delta) = alpha,
// 9.181 for alpha = 0.01, 11.940 for 1. The cells follow the circles
// (meshes/circular-inclusion.geo draws them as arcs). Asked, for every
// contact and alpha: the plateau on 12 cells per quarter circle lies within
// 2% of the exact pressure, closer than on 6. And the polygon: with
// straight cells (Mesh/Curved cells = false) the smooth pile on the thin
// layer carries far more (+23% on 12 cells), every vertex anchoring the
// contact; asked, the curved cells' error is below a fifth of it. And the
// contact's profile follows the circle: on 12 cells its tractions, with
// its normal and tangent at each point, integrate to the pile's reaction
// within 1%. And a thinner layer on a smaller pile: R = 0.5, t = pi R / 480
// (one cell of aspect ratio 10 on 24 cells per quarter), nu = 0.3 in both
// materials, alpha = 0.5 (exact 10.820): its first step once failed even
// at 1/256 of the load factor 4 (every step from rest began with the pile's
// displacement in the layer alone, far beyond yield; the curved layer's
// iterations could not come back from there), and now starts from the
// elastic response; asked, the plateau within 2% (measured +0.4%).
// And the profile is smooth: on 12 cells, at the last converged state, the
// normal traction the run writes (recovered at the nodes from the
// contact's nodal forces, TractionRecovery) stays within 25 c, and no two
// neighbouring samples differ by more than 3 c. The resultant is 9-12 c per
// unit diameter; the raw values at the Gauss points, once the soil flows,
// reach hundreds of c on the interface elements and some 16 c on the
// layer, alternating from point to point.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  /// Randolph and Houlsby's limiting pressure P / (c D) for adhesion
  /// factor @p alpha.
  double
  randolph_houlsby(const double alpha)
  {
    const double delta = std::asin(alpha);
    return M_PI + 2 * delta + 2 * std::cos(delta) +
           4 * (std::cos(delta / 2) + std::sin(delta / 2));
  }

  /**
   * The pile's load (its reaction on the half body) from the newest profile
   * results/@p prefix*.csv of the contact on its circle, @p n Gauss points
   * per cell side: the traction the contact puts on the pile,
   * -sigma_n cos(theta) - tau sin(theta) per unit length, integrated with
   * those points over theta. The profile runs from (-r, 0) to (r, 0), its
   * normal outward (the tangent's quarter turn) and its shear along the
   * run; both follow the circle only if the cells do.
   */
  double
  profile_load(const std::string &prefix, const unsigned int n)
  {
    run_results::Table profile =
      run_results::read_csv(run_results::newest_csv("results", prefix));
    std::sort(profile.begin(), profile.end(), [](const auto &a, const auto &b) {
      return a.at("arc_length") < b.at("arc_length");
    });
    // Gauss abscissae of the side's angle span, and weights (of 1).
    const double spread = n == 2 ? 1 / std::sqrt(3.) : std::sqrt(3. / 5.);
    const std::vector<double> weights =
      n == 2 ? std::vector<double>{0.5, 0.5}
             : std::vector<double>{5. / 18, 8. / 18, 5. / 18};
    double load = 0;
    for (unsigned int k = 0; k + n - 1 < profile.size(); k += n)
      {
        const auto angle = [&](const unsigned int i) {
          return std::atan2(profile[i].at("y"), profile[i].at("x"));
        };
        const double span = std::abs(angle(k + n - 1) - angle(k)) / spread;
        for (unsigned int q = 0; q < n; ++q)
          {
            const auto  &p     = profile[k + q];
            const double theta = angle(k + q);
            const double r     = std::hypot(p.at("x"), p.at("y"));
            load += weights[q] * span * r *
                    (-p.at("normal_traction") * std::cos(theta) -
                     p.at("shear_traction") * std::sin(theta));
          }
      }
    return load;
  }


  /// The largest normal traction of the newest profile
  /// results/@p prefix NNNN.csv, and the largest difference between
  /// neighbouring samples along it, in units of c.
  std::pair<double, double>
  smoothness(const std::string &prefix)
  {
    run_results::Table profile =
      run_results::read_csv(run_results::newest_csv("results", prefix));
    std::sort(profile.begin(), profile.end(), [](const auto &a, const auto &b) {
      return a.at("arc_length") < b.at("arc_length");
    });
    return run_results::spread(profile, "normal_traction");
  }


  /// The plateau of one run: @p zero_thickness picks the scene, @p n the
  /// cells per quarter circle (and 5 n / 3 outwards).
  double
  plateau(const bool         zero_thickness,
          const double       alpha,
          const unsigned int n,
          const bool         curved = true)
  {
    const unsigned int n_radial = 5 * n / 3;
    const std::string  geometry =
      "Mesh/Geometry parameters=radius=1, thickness=0.02, outer=20, "
      "n_around=" +
      std::to_string(n) + ", n_radial=" + std::to_string(n_radial) +
      ", growth=" + std::to_string(std::pow(1.2, 20. / n_radial)) +
      (zero_thickness ? ", zero_thickness=1" : "");
    const std::string strength =
      (zero_thickness ? "Interface 4/Adhesion=" : "Material 2/Cohesion=") +
      std::to_string(alpha);
    return run_results::run_prm(zero_thickness
                                  ? "circular-inclusion-zero-thickness.prm"
                                  : "circular-inclusion.prm",
                                {geometry,
                                 strength,
                                 std::string("Mesh/Curved cells=") +
                                   (curved ? "true" : "false")});
  }
} // namespace


int
main()
{
  using truths::expect;
  double curved_smooth = 0;
  for (const bool zero_thickness : {false, true})
    for (const double alpha : {0.01, 1.})
      {
        const double exact  = randolph_houlsby(alpha);
        const double coarse = plateau(zero_thickness, alpha, 6) / exact - 1;
        const double fine   = plateau(zero_thickness, alpha, 12) / exact - 1;
        // The reaction, from the last converged load (divided by c (R + t)
        // for the skin's outer circle, by c R for the layer's).
        const double reaction =
          run_results::summary_number("results", "last_converged_load") *
          (zero_thickness ? 1.02 : 1.);
        const double from_profile = zero_thickness
                                      ? profile_load("interface-4-", 3)
                                      : profile_load("layer-2-", 2);
        std::printf("%s, alpha = %g: exact %.3f; errors %+.2f%% on 6, %+.2f%% "
                    "on 12 cells per quarter\n",
                    zero_thickness ? "interface elements" : "thin layer",
                    alpha,
                    exact,
                    100 * coarse,
                    100 * fine);
        expect(std::abs(fine) < 0.02 && std::abs(fine) < std::abs(coarse),
               "within 2% on 12, closer than on 6");
        std::printf("  statics on 12: the contact's profile gives %.4f of the "
                    "reaction\n",
                    from_profile / reaction);
        expect(std::abs(from_profile / reaction - 1) < 0.01,
               "the contact's profile carries the pile's load (1%)");
        const auto [largest, jump] =
          smoothness(zero_thickness ? "interface-4-" : "layer-2-");
        std::printf("  the profile on 12: |sigma_n| at most %.1f c, "
                    "neighbours differ by at most %.1f c\n",
                    largest,
                    jump);
        expect(largest < 25 && jump < 3,
               "the contact's normal traction within 25 c, no jump between "
               "neighbours above 3 c");
        if (!zero_thickness && alpha < 0.5)
          curved_smooth = fine;
      }

  const double straight =
    plateau(false, 0.01, 12, false) / randolph_houlsby(0.01) - 1;
  std::printf("straight cells, thin layer, alpha = 0.01, 12 per quarter: "
              "error %+.1f%%\n",
              100 * straight);
  expect(std::abs(curved_smooth) < 0.2 * std::abs(straight),
         "the curved cells' error is below a fifth of the polygon's");

  // The thinner layer on the smaller pile (t = pi R / 480 to five digits):
  // P / (c D) = reaction / (c R), the load scaled by 1 / R.
  const double thin = run_results::run_prm(
    "circular-inclusion.prm",
    {"Mesh/Geometry parameters=radius=0.5, thickness=0.0032725, outer=10, "
     "n_around=24, n_radial=20, growth=1.2",
     "Mesh/Curved cells=true",
     "Material 1/Poisson's ratio=0.3",
     "Material 2/Poisson's ratio=0.3",
     "Material 2/Cohesion=0.5",
     "Monitors/Load scale=2"});
  std::printf("thin layer of aspect ratio 10, R = 0.5, nu = 0.3, alpha = 0.5, "
              "24 per quarter: exact %.3f, error %+.1f%%\n",
              randolph_houlsby(0.5),
              100 * (thin / randolph_houlsby(0.5) - 1));
  expect(std::abs(thin / randolph_houlsby(0.5) - 1) < 0.02,
         "its plateau within 2% of the exact pressure");
  return truths::conclude();
}
