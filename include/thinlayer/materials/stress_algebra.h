#ifndef thinlayer_materials_stress_algebra_h
#define thinlayer_materials_stress_algebra_h

#include <deal.II/base/symmetric_tensor.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The stress invariants the yield criteria are written in (tension
   * positive): mean stress sigma_m = I1/3, equivalent stress
   * sigma_bar = sqrt(3 J2), and the Lode angle
   * theta = 1/3 asin(-3 sqrt(3)/2 J3 / J2^(3/2)) in [-30, 30] degrees, which
   * is +30 degrees in triaxial compression (sigma_1 = sigma_2 > sigma_3) and
   * -30 degrees in triaxial extension.
   */
  struct StressInvariants
  {
    explicit StressInvariants(const SymmetricTensor<2, 3> &stress);

    SymmetricTensor<2, 3> deviator;
    double                mean;
    double                J2;
    double                J3;
    double                equivalent;
    double                lode_angle;
  };


  /**
   * dF/dsigma for F(sigma_m, sigma_bar, theta), from the partial
   * derivatives: d sigma_m = I/3, d sigma_bar = 3 s / (2 sigma_bar),
   * d theta = -tan(3 theta)/(2 J2) s - sqrt(3)/(2 cos(3 theta) J2^1.5)
   * (s.s - 2/3 J2 I).
   */
  SymmetricTensor<2, 3>
  invariant_gradient(const StressInvariants &inv,
                     double                  dF_dmean,
                     double                  dF_dequivalent,
                     double                  dF_dlode);


  /**
   * a (x) b on the stored components: deal.II's outer_product() of
   * symmetric tensors goes through the index accessors, and the
   * consistent tangents call it a dozen times per plastic point, where
   * the accessors' index arithmetic would dominate Newton's iterations.
   * The rank-4 tensor stores the products of the rank-2 components in
   * the same order, without factors.
   */
  inline SymmetricTensor<4, 3>
  outer(const SymmetricTensor<2, 3> &a, const SymmetricTensor<2, 3> &b)
  {
    constexpr unsigned int n = SymmetricTensor<2, 3>::n_independent_components;
    SymmetricTensor<4, 3>  t;
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int q = 0; q < n; ++q)
        t.access_raw_entry(p * n + q) =
          a.access_raw_entry(p) * b.access_raw_entry(q);
    return t;
  }
} // namespace thinlayer

#endif
