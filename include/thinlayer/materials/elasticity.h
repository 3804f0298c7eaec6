#ifndef thinlayer_materials_elasticity_h
#define thinlayer_materials_elasticity_h

#include <deal.II/base/symmetric_tensor.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The isotropic elasticity tensor in 3D, from Young's modulus and
   * Poisson's ratio: C = lambda I(x)I + 2 mu S. Tension is positive.
   */
  inline SymmetricTensor<4, 3>
  isotropic_elasticity(const double youngs_modulus, const double poissons_ratio)
  {
    const double lambda = youngs_modulus * poissons_ratio /
                          ((1 + poissons_ratio) * (1 - 2 * poissons_ratio));
    const double mu = youngs_modulus / (2 * (1 + poissons_ratio));
    return lambda * outer_product(unit_symmetric_tensor<3>(),
                                  unit_symmetric_tensor<3>()) +
           2 * mu * identity_tensor<3>();
  }

  /**
   * The equivalent stress sqrt(3 J2) (von Mises stress).
   */
  inline double
  equivalent_stress(const SymmetricTensor<2, 3> &stress)
  {
    const SymmetricTensor<2, 3> s = deviator(stress);
    return std::sqrt(1.5 * (s * s));
  }
} // namespace thinlayer

#endif
