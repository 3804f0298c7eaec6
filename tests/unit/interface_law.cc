// Truths checked for the zero-thickness interface law (local frame: s
// along, n normal with tension positive, t out of plane):
// - the return mapping's consistent tangent against central finite
//   differences of the returned traction as a function of the relative
//   displacement (trial = t0 + K delta), on random trials in each region
//   (elastic, slip, tension cut-off, corner), for Tresca, associated and
//   non-associated Mohr-Coulomb, with shear in the plane alone (plane
//   strain) and out of it too (Fourier);
// - every returned traction is admissible: f <= 0 to round-off, and on
//   the surface of its region;
// - slip keeps the shear direction of the trial, and the plastic jump is
//   along the plastic potential's gradient: its normal part over its shear
//   part is tan(psi).
#include <thinlayer/materials/interface_law.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "../common/material_test_utilities.h"

using namespace dealii;
using namespace thinlayer;

namespace
{
  thinlayer_tests::PseudoRandom random_numbers(2024);

  InterfaceElementParameters
  curve(const InterfaceElementParameters::Criterion criterion,
        const double                                phi,
        const double                                psi,
        const double                                tension)
  {
    InterfaceElementParameters p;
    p.normal_stiffness = 2000;
    p.shear_stiffness  = 700;
    p.criterion        = criterion;
    p.adhesion         = 1;
    p.friction_angle   = phi;
    p.dilation_angle   = psi;
    p.tensile_strength = tension;
    return p;
  }

  const char *
  region_name(const InterfaceReturn r)
  {
    switch (r)
      {
        case InterfaceReturn::elastic:
          return "elastic";
        case InterfaceReturn::slip:
          return "slip";
        case InterfaceReturn::tension:
          return "tension";
        case InterfaceReturn::corner:
          return "corner";
      }
    return "";
  }

  void
  check(const std::string &title, const InterfaceElementParameters &p)
  {
    const InterfaceLaw law(p);
    // Per region: trials met, largest tangent error, largest f, worst
    // flow-rule mismatch.
    std::map<std::string, std::array<double, 4>> worst;
    for (const bool out_of_plane : {false, true})
      for (unsigned int k = 0; k < 400; ++k)
        {
          const Tensor<1, 3> t0(
            {4 * (2 * random_numbers.next() - 1),
             4 * (2 * random_numbers.next() - 1),
             out_of_plane ? 4 * (2 * random_numbers.next() - 1) : 0.});
          Tensor<1, 3> delta;
          const auto   evaluate = [&](const Tensor<1, 3> &d) {
            return law.return_mapping(t0 + law.elastic_traction(d), true);
          };
          const InterfaceReturnMapping r = evaluate(delta);
          auto                        &w = worst[region_name(r.region)];
          w[0] += 1;
          // Central differences over delta; skip the points within h of a
          // region boundary (a kink).
          const double h    = 1e-7;
          bool         kink = false;
          Tensor<2, 3> fd;
          for (unsigned int j = 0; j < 3; ++j)
            {
              if (!out_of_plane && j == 2)
                continue;
              Tensor<1, 3> plus = delta, minus = delta;
              plus[j] += h;
              minus[j] -= h;
              const auto rp = evaluate(plus), rm = evaluate(minus);
              kink = kink || rp.region != r.region || rm.region != r.region;
              for (unsigned int i = 0; i < 3; ++i)
                fd[i][j] = (rp.traction[i] - rm.traction[i]) / (2 * h);
            }
          if (!kink)
            {
              double error = 0;
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = 0; j < 3; ++j)
                  if (out_of_plane || j < 2)
                    error =
                      std::max(error, std::abs(fd[i][j] - r.tangent[i][j]));
              w[1] = std::max(w[1], error / 2000);
            }
          w[2] = std::max(w[2], law.yield_function(r.traction));
          if (r.region == InterfaceReturn::slip)
            {
              const Tensor<1, 3> trial = t0;
              const Tensor<1, 3> jump = law.compliance() * (trial - r.traction);
              const double       shear =
                std::sqrt(jump[0] * jump[0] + jump[2] * jump[2]);
              const double dilation = std::tan(p.dilation_angle * M_PI / 180);
              // Plastic jump along dQ/dt: normal over shear is tan(psi),
              // the shear part along the trial's shear.
              double       mismatch = std::abs(jump[1] - dilation * shear);
              const double cross =
                trial[0] * r.traction[2] - trial[2] * r.traction[0];
              mismatch = std::max(mismatch, std::abs(cross));
              w[3]     = std::max(w[3], mismatch);
            }
        }
    std::printf("%s\n", title.c_str());
    for (const auto &[region, w] : worst)
      std::printf("  %-8s trials %3d: tangent against differences %s, "
                  "admissible %s%s\n",
                  region.c_str(),
                  static_cast<int>(w[0]),
                  w[1] < 1e-6 ? "agrees" : "DIFFERS",
                  w[2] < 1e-9 ? "yes" : "NO",
                  region == "slip"
                    ? (w[3] < 1e-9 ? ", flow along dQ/dt" : ", flow WRONG")
                    : "");
  }
} // namespace


int
main()
{
  using C           = InterfaceElementParameters::Criterion;
  const double none = std::numeric_limits<double>::infinity();
  check("Tresca, c = 1", curve(C::tresca, 0, 0, none));
  check("Tresca, c = 1, tension cut-off 0.5", curve(C::tresca, 0, 0, 0.5));
  check("Mohr-Coulomb, c = 1, phi = psi = 30, cut-off at the apex",
        curve(C::mohr_coulomb, 30, 30, 1 / std::tan(M_PI / 6)));
  check("Mohr-Coulomb, c = 1, phi = 30, psi = 10, cut-off 0.5",
        curve(C::mohr_coulomb, 30, 10, 0.5));
  check("Mohr-Coulomb, c = 1, phi = 20, psi = 0, cut-off 0",
        curve(C::mohr_coulomb, 20, 0, 0));
}
