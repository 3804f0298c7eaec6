// Truth checked: the passive earth pressure on a rough vertical wall
// (cohesionless backfill with weight, phi = 30, associated flow; the wall
// pushed into it, held vertically; the soil going on below the toe) lies
// between the two classical solutions that bracket the exact one, for a
// wall friction delta/phi = 1/3, 2/3 and 1, carried by a thin column of
// elements (prm/earth-pressure-passive-wall-friction.prm:
// sin(phi_w) = tan(delta), no dilation, Davis 1968) and by zero-thickness
// interface elements
// (prm/earth-pressure-passive-wall-friction-zero-thickness.prm):
//  - Lancellotta (2002, Geotechnique 52(8) 617-619): a stress field in
//    equilibrium and nowhere above yield, so the exact normal thrust
//    coefficient is at least
//    K_L = cos(delta) / (1 - sin(phi))
//          (cos(delta) + sqrt(sin^2(phi) - sin^2(delta))) e^(2 theta tan(phi)),
//    2 theta = asin(sin(delta) / sin(phi)) + delta;
//  - Coulomb (1776): the plane sliding wedge is a mechanism, so the exact
//    coefficient is at most the normal component of Coulomb's,
//    cos(delta) cos^2(phi) / (1 - sqrt(sin(phi + delta) sin(phi) /
//    cos(delta)))^2 (the bound theorems of plasticity; Chen 1975).
// A displacement method overestimates the soil's strength, so its passive
// thrust lies above the exact one and falls with refinement, first order
// here once the cells below the toe are graded with the mesh (measured,
// interface elements, delta = 20: 5.298, 5.115, 5.028 on 12, 24 and 48
// cells up the wall, the differences falling by 2.1; thin column,
// delta = 10: 4.196, 4.058, 3.999, by 2.3). Checked on 12 cells
// for every delta: the thrust lies above Lancellotta's and rises with
// delta; and on 24 cells for one delta of each kind (the thin column at
// delta = 10, the interface elements at delta = 20; the report runs every
// delta on both meshes): the thrust falls with refinement and its
// first-order extrapolation 2 K_fine - K_coarse lies inside
// [K_L, K_Coulomb]. The thin column at delta = phi (phi_w = 35.3 degrees)
// is left out: the default method does not converge there on 12 cells.

#include <cmath>
#include <cstdio>

#include "../common/truths.h"
#include "../common/wall_backfill.h"

namespace
{
  const double phi = 30;

  using wall_backfill::radians;


  /// The passive thrust with wall friction @p delta on @p n x 2 n cells
  /// (and n / 2 below the toe), the grading away from the wall and down
  /// from the toe halved with the cells: (1.1, 1.3) on 12 cells; the
  /// files' column (H / 50) or skin (H / 200).
  double
  thrust(const bool interface, const double delta, const unsigned int n)
  {
    char geometry[192];
    std::snprintf(geometry,
                  sizeof(geometry),
                  "height=1, width=4, layer=%g, n_height=%u, n_width=%u, "
                  "growth=%.6g, depth=1, n_depth=%u, depth_growth=%.6g",
                  interface ? 0.005 : 0.02,
                  n,
                  2 * n,
                  std::pow(1.1, 12. / n),
                  n / 2,
                  std::pow(1.3, 12. / n));
    return wall_backfill::thrust("earth-pressure-passive-wall-friction",
                                 interface,
                                 delta,
                                 geometry);
  }
} // namespace


int
main()
{
  using truths::expect;
  const double p       = radians(phi);
  const double rankine = (1 + std::sin(p)) / (1 - std::sin(p));
  for (const bool interface : {false, true})
    {
      double previous = rankine;
      for (const double delta : {10., 20., 30.})
        {
          if (!interface && delta == phi)
            continue;
          const double d = radians(delta);
          const double root =
            std::sqrt(std::sin(p + d) * std::sin(p) / std::cos(d));
          const double coulomb =
            std::cos(d) * std::pow(std::cos(p), 2) / std::pow(1 - root, 2);
          const double two_theta = std::asin(std::sin(d) / std::sin(p)) + d;
          const double lancellotta =
            std::cos(d) / (1 - std::sin(p)) *
            (std::cos(d) +
             std::sqrt(std::pow(std::sin(p), 2) - std::pow(std::sin(d), 2))) *
            std::exp(two_theta * std::tan(p));
          const double coarse = thrust(interface, delta, 12);
          std::printf("%s, delta = %2.0f: K = %.3f on 12 x 24; bracket "
                      "[%.4f, %.4f]\n",
                      interface ? "interface elements" : "thin column",
                      delta,
                      coarse,
                      lancellotta,
                      coulomb);
          expect(coarse > lancellotta, "the thrust lies above Lancellotta's");
          expect(coarse > previous, "the thrust rises as delta grows");
          previous = coarse;
          if (delta != (interface ? 20. : 10.))
            continue;
          const double fine         = thrust(interface, delta, 24);
          const double extrapolated = 2 * fine - coarse;
          std::printf("  %.3f on 24 x 48, extrapolated %.2f\n",
                      fine,
                      extrapolated);
          expect(fine < coarse, "the thrust falls with refinement");
          expect(extrapolated >= lancellotta && extrapolated <= coulomb,
                 "the extrapolation lies between Lancellotta's and "
                 "Coulomb's");
        }
    }
  return truths::conclude();
}
