// Truths checked for the material laws (tension positive):
// - invariants and Lode angle on known states: uniaxial compression is
//   theta = +30 degrees, uniaxial tension -30, pure shear 0;
// - F against formulas in principal stresses, computed here from the
//   eigenvalues: Tresca (s1 - s3)/2 - c, von Mises sqrt(3 J2) - sqrt(3) c,
//   Mohr-Coulomb (s1 - s3)/2 + (s1 + s3)/2 sin(phi) - c cos(phi), on random
//   stress states, both general ones and ones with no shear out of the x-y
//   plane (plane strain, for which the laws take a shortcut), and F = 0 on
//   states built to lie on each surface;
// - flow directions dQ/dsigma against central finite differences of Q
//   (for Mohr-Coulomb with psi != phi, Q is F with psi for phi), away from
//   the corners of the hexagon;
// - at a corner (two equal principal stresses) the flow direction is the
//   average of the gradients of the two faces meeting there;
// - the elastic stress in Lame form equals the elasticity tensor applied to
//   the strain.
#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/materials/material_law.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../common/material_test_utilities.h"

using namespace dealii;
using namespace thinlayer;
using namespace thinlayer_tests;

namespace
{
  PseudoRandom random_numbers(12345);

  SymmetricTensor<2, 3>
  random_stress(const double scale)
  {
    return random_numbers.stress(scale);
  }

  // Principal stresses, largest first.
  std::array<double, 3>
  principal(const SymmetricTensor<2, 3> &s)
  {
    return eigenvalues(s);
  }

  // Central finite differences of F, as a symmetric tensor of dF/dsigma.
  SymmetricTensor<2, 3>
  finite_difference_gradient(const MaterialLaw           &law,
                             const SymmetricTensor<2, 3> &s)
  {
    const double          h = 1e-6 * s.norm();
    SymmetricTensor<2, 3> g;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        {
          SymmetricTensor<2, 3> plus = s, minus = s;
          plus[i][j] += h;
          minus[i][j] -= h;
          // Moving a symmetric off-diagonal entry moves both sigma_ij and
          // sigma_ji, so the difference quotient is twice dF/dsigma_ij.
          g[i][j] = (law.yield_function(plus) - law.yield_function(minus)) /
                    (2 * h) / (i == j ? 1 : 2);
        }
    return g;
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "NO";
  }
} // namespace

int
main()
{
  const double degree = numbers::PI / 180;

  std::printf("Invariants (sigma_m, sigma_bar, Lode angle in degrees):\n");
  for (const auto &[name, diagonal] :
       {std::make_pair("uniaxial compression", Tensor<1, 3>({0., 0., -3.})),
        std::make_pair("uniaxial tension", Tensor<1, 3>({3., 0., 0.})),
        std::make_pair("pure shear", Tensor<1, 3>({1., 0., -1.})),
        std::make_pair("hydrostatic", Tensor<1, 3>({-2., -2., -2.}))})
    {
      SymmetricTensor<2, 3> s;
      for (unsigned int i = 0; i < 3; ++i)
        s[i][i] = diagonal[i];
      const StressInvariants inv(s);
      std::printf("  %-21s %8.4f %8.4f %8.4f\n",
                  name,
                  inv.mean,
                  inv.equivalent,
                  inv.lode_angle / degree + 0.0);
    }

  const double c = 2.0, phi = 30 * degree, psi = 10 * degree;
  const auto tresca = create_material_law(material(YieldCriterion::tresca, c));
  const auto mises =
    create_material_law(material(YieldCriterion::von_mises, c));
  const auto mohr_coulomb =
    create_material_law(material(YieldCriterion::mohr_coulomb, c, 30, 10));
  // F of this one is the plastic potential Q of mohr_coulomb.
  const auto mohr_coulomb_potential =
    create_material_law(material(YieldCriterion::mohr_coulomb, c, 10, 10));
  const auto associated =
    create_material_law(material(YieldCriterion::mohr_coulomb, c, 30, 30));

  std::printf("\nYield functions against principal-stress formulas "
              "(2000 random states, half of them plane):\n");
  double tresca_error = 0, mises_error = 0, mc_error = 0;
  for (unsigned int k = 0; k < 2000; ++k)
    {
      SymmetricTensor<2, 3> s = random_stress(5);
      if (k % 2 == 1)
        s[0][2] = s[1][2] = 0; // plane strain
      const auto   p = principal(s);
      const double j2 =
        ((p[0] - p[1]) * (p[0] - p[1]) + (p[1] - p[2]) * (p[1] - p[2]) +
         (p[2] - p[0]) * (p[2] - p[0])) /
        6;
      tresca_error =
        std::max(tresca_error,
                 std::abs(tresca->yield_function(s) - ((p[0] - p[2]) / 2 - c)));
      mises_error = std::max(mises_error,
                             std::abs(mises->yield_function(s) -
                                      (std::sqrt(3 * j2) - std::sqrt(3.) * c)));
      mc_error    = std::max(mc_error,
                          std::abs(mohr_coulomb->yield_function(s) -
                                   ((p[0] - p[2]) / 2 +
                                    (p[0] + p[2]) / 2 * std::sin(phi) -
                                    c * std::cos(phi))));
    }
  std::printf("  Tresca agrees to 1e-12: %s\n", yes_no(tresca_error < 1e-12));
  std::printf("  von Mises agrees to 1e-12: %s\n", yes_no(mises_error < 1e-12));
  std::printf("  Mohr-Coulomb agrees to 1e-12: %s\n", yes_no(mc_error < 1e-12));

  std::printf("\nStates on the surfaces (F there, and 1%% outside):\n");
  {
    // Tresca: s1 - s3 = 2c; von Mises in plane-strain pure shear: tau = c;
    // Mohr-Coulomb: uniaxial compression 2 c cos(phi)/(1 - sin(phi)).
    SymmetricTensor<2, 3> shear;
    shear[0][1] = c;
    SymmetricTensor<2, 3> compression;
    compression[2][2] = -2 * c * std::cos(phi) / (1 - std::sin(phi));
    for (const auto &[name, law, s] :
         {std::make_tuple("Tresca, shear tau = c", tresca.get(), shear),
          std::make_tuple("von Mises, shear tau = c", mises.get(), shear),
          std::make_tuple("Mohr-Coulomb, uniaxial compression",
                          mohr_coulomb.get(),
                          compression)})
      std::printf("  %-36s F = %.2e, yield ratio 1%% outside = %.4f\n",
                  name,
                  std::abs(law->yield_function(s)) < 1e-12
                    ? 0.
                    : law->yield_function(s),
                  law->yield_ratio(1.01 * s));

    // The mobilised strength tau_mob / tau_max: 1 on the surface and
    // beyond it, 1/2 at half the surface's shear (the mean stress kept),
    // in [0, 1] everywhere (1000 random states), 0 for an elastic law.
    SymmetricTensor<2, 3> half_compression = compression;
    const double          mean             = compression[2][2] / 2;
    half_compression[2][2] = mean + (compression[2][2] - mean) / 2;
    half_compression[0][0] = mean - (compression[2][2] - mean) / 2;
    half_compression[1][1] = half_compression[0][0];
    // Its Mohr circle has half the radius of the uniaxial one about the
    // same centre.
    bool in_range = true;
    for (unsigned int k = 0; k < 1000; ++k)
      {
        const SymmetricTensor<2, 3> r = random_stress(5 * c);
        for (const MaterialLaw *law :
             {tresca.get(), mises.get(), mohr_coulomb.get()})
          in_range = in_range && law->mobilised_strength(r) >= 0 &&
                     law->mobilised_strength(r) <= 1;
      }
    const auto elastic =
      create_material_law(material(YieldCriterion::elastic, c));
    const double surfaces = std::max(
      {std::abs(tresca->mobilised_strength(shear) - 1),
       std::abs(mises->mobilised_strength(shear) - 1),
       std::abs(mohr_coulomb->mobilised_strength(compression) - 1),
       std::abs(mohr_coulomb->mobilised_strength(1.01 * compression) - 1)});
    const double halves = std::max(
      {std::abs(tresca->mobilised_strength(0.5 * shear) - 0.5),
       std::abs(mises->mobilised_strength(0.5 * shear) - 0.5),
       std::abs(mohr_coulomb->mobilised_strength(half_compression) - 0.5)});
    std::printf(
      "  mobilised strength: on the surfaces and 1%% outside 1 to 1e-12: %s; "
      "at half the shear 1/2 to 1e-12: %s; elastic 0: %s; in [0, 1] for "
      "1000 random states: %s\n",
      yes_no(surfaces < 1e-12),
      yes_no(halves < 1e-12),
      yes_no(elastic->mobilised_strength(shear) == 0),
      yes_no(in_range));
  }

  std::printf("\nFlow directions against central differences "
              "(1000 random states, |theta| < 25 degrees):\n");
  for (const auto &[name, law, potential] :
       {std::make_tuple("Tresca", tresca.get(), tresca.get()),
        std::make_tuple("von Mises", mises.get(), mises.get()),
        std::make_tuple("Mohr-Coulomb, associated",
                        associated.get(),
                        associated.get()),
        std::make_tuple("Mohr-Coulomb, psi = 10, phi = 30",
                        mohr_coulomb.get(),
                        mohr_coulomb_potential.get())})
    {
      double       max_error = 0;
      unsigned int tested    = 0;
      while (tested < 1000)
        {
          const SymmetricTensor<2, 3> s = random_stress(5);
          if (std::abs(StressInvariants(s).lode_angle) > 25 * degree)
            continue;
          ++tested;
          const SymmetricTensor<2, 3> exact = law->flow_direction(s);
          const SymmetricTensor<2, 3> fd =
            finite_difference_gradient(*potential, s);
          max_error = std::max(max_error, (exact - fd).norm() / fd.norm());
        }
      std::printf("  %-33s relative difference below 1e-6: %s\n",
                  name,
                  yes_no(max_error < 1e-6));
    }

  std::printf("\nFlow directions at corners against the average of the two "
              "faces:\n");
  for (const double sign : {+1., -1.})
    {
      // sigma = diag(a, a, b): two equal principal stresses. With b < a this
      // is triaxial compression (theta = +30), with b > a extension.
      const double          a = -1, b = -1 - sign * 3;
      SymmetricTensor<2, 3> s;
      s[0][0] = s[1][1] = a;
      s[2][2]           = b;
      // The faces (s_i - s_k)/2 + (s_i + s_k)/2 sin(psi) for the two
      // orderings of the equal pair; their gradients are diagonal.
      const double          sp = std::sin(psi);
      SymmetricTensor<2, 3> average;
      if (sign > 0) // s1 = s2 = a > s3 = b: faces (1,3) and (2,3)
        {
          average[0][0] = average[1][1] = (1 + sp) / 4;
          average[2][2]                 = (-1 + sp) / 2;
        }
      else // s1 = b > s2 = s3 = a: faces (1,2) and (1,3)
        {
          average[2][2] = (1 + sp) / 2;
          average[0][0] = average[1][1] = (-1 + sp) / 4;
        }
      const SymmetricTensor<2, 3> computed = mohr_coulomb->flow_direction(s);
      std::printf("  Lode angle %+5.1f: matches to 1e-12: %s\n",
                  StressInvariants(s).lode_angle / degree,
                  yes_no((computed - average).norm() < 1e-12));
    }

  {
    // The Lame form of the elastic stress against the elasticity tensor.
    double difference = 0;
    for (unsigned int k = 0; k < 100; ++k)
      {
        const SymmetricTensor<2, 3> strain = random_stress(1e-3);
        difference                         = std::max(difference,
                              (mohr_coulomb->elastic_stress(strain) -
                               mohr_coulomb->elasticity() * strain)
                                  .norm() /
                                (mohr_coulomb->elasticity() * strain).norm());
      }
    std::printf("\nElastic stress (Lame form) equals elasticity() * strain "
                "to 1e-14 (100 random strains): %s\n",
                yes_no(difference < 1e-14));
  }

  std::printf("\nPseudo time steps for E = 1000, nu = 0.3:\n"
              "  Tresca %.6e\n  von Mises %.6e\n  Mohr-Coulomb (phi = 30) "
              "%.6e\n",
              tresca->viscoplastic_time_step(),
              mises->viscoplastic_time_step(),
              mohr_coulomb->viscoplastic_time_step());
}
