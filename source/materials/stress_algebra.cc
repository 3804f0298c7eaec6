#include <thinlayer/materials/stress_algebra.h>

#include <algorithm>
#include <cmath>

namespace thinlayer
{
  StressInvariants::StressInvariants(const SymmetricTensor<2, 3> &stress)
    : deviator(dealii::deviator(stress))
    , mean(trace(stress) / 3)
    , J2(0.5 * (deviator * deviator))
    , J3(determinant(deviator))
    , equivalent(std::sqrt(3 * J2))
    , lode_angle(0)
  {
    if (J2 > 0)
      {
        const double z = -1.5 * std::sqrt(3.) * J3 / std::pow(J2, 1.5);
        lode_angle     = std::asin(std::clamp(z, -1., 1.)) / 3;
      }
  }


  SymmetricTensor<2, 3>
  invariant_gradient(const StressInvariants &inv,
                     const double            dF_dmean,
                     const double            dF_dequivalent,
                     const double            dF_dlode)
  {
    SymmetricTensor<2, 3> gradient =
      (dF_dmean / 3.) * unit_symmetric_tensor<3>();
    if (inv.equivalent <= 0)
      return gradient; // the apex: only the volumetric part is defined
    gradient += (1.5 * dF_dequivalent / inv.equivalent) * inv.deviator;
    if (dF_dlode != 0)
      {
        const double cos3 = std::cos(3 * inv.lode_angle);
        const double tan3 = std::tan(3 * inv.lode_angle);
        // dJ3/dsigma = s.s - 2/3 J2 I (the matrix product s.s).
        const Tensor<2, 3>    s(inv.deviator);
        SymmetricTensor<2, 3> dJ3 =
          symmetrize(s * s) - (2. / 3.) * inv.J2 * unit_symmetric_tensor<3>();
        gradient +=
          dF_dlode * (-tan3 / (2 * inv.J2) * inv.deviator -
                      std::sqrt(3.) / (2 * cos3 * std::pow(inv.J2, 1.5)) * dJ3);
      }
    return gradient;
  }
} // namespace thinlayer
