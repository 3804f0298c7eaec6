// Truths checked for the return mappings and their consistent tangents
// (tension positive), on random trial stresses spread so that every region
// of each surface is reached (main plane, both edges, the Mohr-Coulomb
// apex):
// - the returned stress lies on the yield surface (|F| / c below 1e-10);
// - it is the closest point in the energy norm for associated laws:
//   (trial - sigma) : C^-1 : (tau - sigma) <= 0 for every admissible tau
//   (checked against random admissible stresses), which holds only for the
//   projection onto a convex set;
// - for non-associated Mohr-Coulomb on the main plane, the plastic strain
//   C^-1 (trial - sigma) is parallel to the flow direction dQ/dsigma;
// - the consistent tangent agrees with central finite differences of the
//   return mapping (samples whose differences cross into another region
//   are skipped and counted), and is symmetric for associated laws;
// - admissible trial stresses come back unchanged with the elastic tangent.
#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/materials/material_law.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

#include "../common/material_test_utilities.h"

using namespace dealii;
using namespace thinlayer;
using namespace thinlayer_tests;

namespace
{
  PseudoRandom random_numbers(424242);

  SymmetricTensor<2, 3>
  random_stress(const double deviatoric_scale, const double mean_scale)
  {
    // Two statements: the deviator's entries are drawn before the mean.
    const SymmetricTensor<2, 3> s = random_numbers.stress(deviatoric_scale);
    return deviator(s) + mean_scale * (2 * random_numbers.next() - 1) *
                           unit_symmetric_tensor<3>();
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }

  const char *
  region_name(const ReturnRegion r)
  {
    switch (r)
      {
        case ReturnRegion::elastic:
          return "elastic";
        case ReturnRegion::surface:
          return "surface";
        case ReturnRegion::edge_s1_equals_s2:
          return "edge s1 = s2";
        case ReturnRegion::edge_s2_equals_s3:
          return "edge s2 = s3";
        case ReturnRegion::apex:
          return "apex";
      }
    return "";
  }

  // The basis tensor of the Voigt-like index k of a symmetric tensor.
  SymmetricTensor<2, 3>
  unit_strain(const unsigned int k)
  {
    SymmetricTensor<2, 3> e;
    const auto ij   = SymmetricTensor<2, 3>::unrolled_to_component_indices(k);
    e[ij[0]][ij[1]] = 1;
    return e;
  }

  /// Checks the return mapping of @p law; @p principal_F is its yield
  /// function in the principal stresses, largest first.
  template <typename PrincipalF>
  void
  check(const char        *name,
        const MaterialLaw &law,
        const double       c,
        const PrincipalF  &principal_F)
  {
    const SymmetricTensor<4, 3>        &D = law.elasticity();
    const SymmetricTensor<4, 3>        &C = law.compliance();
    std::map<std::string, unsigned int> regions;
    double       max_F = 0, max_tangent_error = 0, max_asymmetry = 0;
    double       max_flow_error    = 0;
    bool         closest           = true;
    bool         elastic_unchanged = true;
    unsigned int fd_skipped = 0, fd_tested = 0;

    for (unsigned int sample = 0; sample < 2000; ++sample)
      {
        // Every fourth trial stress is nearly hydrostatic and far on the
        // tension side, to reach the apex of Mohr-Coulomb.
        const SymmetricTensor<2, 3> trial =
          (sample % 4 == 3)
            ? random_stress(c, 3 * c) + 7 * c * unit_symmetric_tensor<3>()
            : random_stress(4 * c, 6 * c);
        const ReturnMapping r = law.return_mapping(trial);
        ++regions[region_name(r.region)];

        if (r.region == ReturnRegion::elastic)
          {
            elastic_unchanged = elastic_unchanged && (r.stress == trial) &&
                                ((r.tangent - D).norm() == 0);
            continue;
          }
        {
          // F from the principal stresses, in the eigenvectors of the
          // trial stress (an isotropic return keeps them): the Lode-angle
          // form of F loses half the digits at the corners of the
          // hexagon, where asin has an infinite slope.
          const auto            eig = eigenvectors(trial);
          std::array<double, 3> p;
          for (unsigned int i = 0; i < 3; ++i)
            {
              p[i] = eig[i].second * (r.stress * eig[i].second);
              for (unsigned int j = i + 1; j < 3; ++j)
                max_F = std::max(
                  max_F,
                  std::abs(eig[i].second * (r.stress * eig[j].second)) / c);
            }
          std::sort(p.begin(), p.end(), std::greater<double>());
          max_F = std::max(max_F, std::abs(principal_F(p)) / c);
        }

        if (law.is_associated())
          for (unsigned int k = 0; k < 50; ++k)
            {
              const SymmetricTensor<2, 3> tau = random_stress(2 * c, 6 * c);
              if (law.yield_function(tau) > 0)
                continue;
              if ((trial - r.stress) * (C * (tau - r.stress)) >
                  1e-10 * c * c / D[0][0][0][0])
                closest = false;
            }
        else if (r.region == ReturnRegion::surface &&
                 std::abs(StressInvariants(r.stress).lode_angle) <
                   25 * numbers::PI / 180)
          {
            const SymmetricTensor<2, 3> plastic = C * (trial - r.stress);
            const SymmetricTensor<2, 3> flow    = law.flow_direction(r.stress);
            max_flow_error =
              std::max(max_flow_error,
                       (plastic / plastic.norm() - flow / flow.norm()).norm());
          }

        // Central differences of the return in the strain: the trial
        // stress moves by D : (h e_k).
        const double          h           = 1e-7 * trial.norm() / D[0][0][0][0];
        bool                  same_region = true;
        SymmetricTensor<4, 3> fd;
        for (unsigned int k = 0; k < 6; ++k)
          {
            const SymmetricTensor<2, 3> dtrial = D * (h * unit_strain(k));
            const ReturnMapping plus  = law.return_mapping(trial + dtrial);
            const ReturnMapping minus = law.return_mapping(trial - dtrial);
            same_region = same_region && plus.region == r.region &&
                          minus.region == r.region;
            const SymmetricTensor<2, 3> column =
              (plus.stress - minus.stress) / (2 * h);
            // unit_strain(k) has one entry for k < 3 and two (ij and ji)
            // for shears, so the column is d sigma / d eps_ij times 1 or 2.
            const auto ij =
              SymmetricTensor<2, 3>::unrolled_to_component_indices(k);
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = a; b < 3; ++b)
                fd[a][b][ij[0]][ij[1]] = column[a][b] / (k < 3 ? 1. : 2.);
          }
        if (!same_region)
          {
            ++fd_skipped;
            continue;
          }
        ++fd_tested;
        max_tangent_error =
          std::max(max_tangent_error, (fd - r.tangent).norm() / D.norm());
        for (unsigned int a = 0; a < 6; ++a)
          for (unsigned int b = 0; b < 6; ++b)
            {
              const auto ij =
                SymmetricTensor<2, 3>::unrolled_to_component_indices(a);
              const auto kl =
                SymmetricTensor<2, 3>::unrolled_to_component_indices(b);
              max_asymmetry =
                std::max(max_asymmetry,
                         std::abs(r.tangent[ij[0]][ij[1]][kl[0]][kl[1]] -
                                  r.tangent[kl[0]][kl[1]][ij[0]][ij[1]]) /
                           D.norm());
            }
      }

    std::printf("%s\n  regions:", name);
    for (const auto &[region, count] : regions)
      std::printf(" %s %u,", region.c_str(), count);
    std::printf(
      "\n  returned stress coaxial and on the surface (|F|/c < 1e-10): %s\n",
      yes_no(max_F < 1e-10));
    std::printf("  admissible trial stresses unchanged, elastic tangent: %s\n",
                yes_no(elastic_unchanged));
    if (law.is_associated())
      {
        std::printf("  closest point in the energy norm: %s\n",
                    yes_no(closest));
        std::printf("  tangent symmetric (to 1e-10): %s\n",
                    yes_no(max_asymmetry < 1e-10));
      }
    else
      std::printf("  plastic strain along dQ/dsigma on the main plane (to "
                  "1e-8): %s\n",
                  yes_no(max_flow_error < 1e-8));
    std::printf("  tangent against central differences (relative to |D|, "
                "below 1e-6): %s (%u tested, %u straddling a region "
                "boundary skipped)\n",
                yes_no(max_tangent_error < 1e-6),
                fd_tested,
                fd_skipped);
  }

} // namespace


int
main()
{
  const double c              = 2.0;
  const auto   mohr_coulomb_F = [c](const double phi) {
    return [c, phi](const std::array<double, 3> &p) {
      return (p[0] - p[2]) / 2 + (p[0] + p[2]) / 2 * std::sin(phi) -
             c * std::cos(phi);
    };
  };
  const double degree = numbers::PI / 180;
  check("Tresca",
        *create_material_law(material(YieldCriterion::tresca, c)),
        c,
        mohr_coulomb_F(0));
  check("von Mises",
        *create_material_law(material(YieldCriterion::von_mises, c)),
        c,
        [c](const std::array<double, 3> &p) {
          return std::sqrt(((p[0] - p[1]) * (p[0] - p[1]) +
                            (p[1] - p[2]) * (p[1] - p[2]) +
                            (p[2] - p[0]) * (p[2] - p[0])) /
                           2) -
                 std::sqrt(3.) * c;
        });
  for (const double psi : {30., 10., 0.})
    {
      const std::string name =
        "Mohr-Coulomb, phi = 30, psi = " + std::to_string(int(psi));
      check(name.c_str(),
            *create_material_law(
              material(YieldCriterion::mohr_coulomb, c, 30, psi)),
            c,
            mohr_coulomb_F(30 * degree));
    }
}
