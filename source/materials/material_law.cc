#include <thinlayer/materials/elasticity.h>
#include <thinlayer/materials/material_law.h>
#include <thinlayer/materials/mohr_coulomb.h>
#include <thinlayer/materials/von_mises.h>
#include <thinlayer/parameters/parameters.h>

#include <limits>

namespace thinlayer
{
  MaterialLaw::MaterialLaw(const double youngs_modulus,
                           const double poissons_ratio)
    : youngs_modulus(youngs_modulus)
    , poissons_ratio(poissons_ratio)
    , stiffness(isotropic_elasticity(youngs_modulus, poissons_ratio))
    , inverse_stiffness(invert(stiffness))
    , lame_lambda(youngs_modulus * poissons_ratio /
                  ((1 + poissons_ratio) * (1 - 2 * poissons_ratio)))
    , shear_modulus(youngs_modulus / (2 * (1 + poissons_ratio)))
  {}


  const SymmetricTensor<4, 3> &
  MaterialLaw::compliance() const
  {
    return inverse_stiffness;
  }


  ReturnMapping
  MaterialLaw::return_mapping(const SymmetricTensor<2, 3> &trial,
                              const bool /*with_tangent*/) const
  {
    return {trial, stiffness, ReturnRegion::elastic};
  }


  bool
  MaterialLaw::is_associated() const
  {
    return true;
  }


  const SymmetricTensor<4, 3> &
  MaterialLaw::elasticity() const
  {
    return stiffness;
  }


  bool
  MaterialLaw::can_yield() const
  {
    return false;
  }


  double
  MaterialLaw::yield_function(const SymmetricTensor<2, 3> &) const
  {
    return -std::numeric_limits<double>::infinity();
  }


  SymmetricTensor<2, 3>
  MaterialLaw::flow_direction(const SymmetricTensor<2, 3> &) const
  {
    return SymmetricTensor<2, 3>();
  }


  double
  MaterialLaw::yield_ratio(const SymmetricTensor<2, 3> &) const
  {
    return -std::numeric_limits<double>::infinity();
  }


  double
  MaterialLaw::mobilised_strength(const SymmetricTensor<2, 3> &) const
  {
    return 0;
  }


  double
  MaterialLaw::viscoplastic_time_step() const
  {
    return std::numeric_limits<double>::infinity();
  }


  std::unique_ptr<MaterialLaw>
  create_material_law(const MaterialParameters &m)
  {
    const double E = m.youngs_modulus, nu = m.poissons_ratio;
    const double degree = numbers::PI / 180;
    switch (m.yield_criterion)
      {
        case YieldCriterion::elastic:
          return std::make_unique<Elastic>(E, nu);
        case YieldCriterion::tresca:
          return std::make_unique<MohrCoulomb>(E, nu, m.cohesion, 0, 0);
        case YieldCriterion::von_mises:
          return std::make_unique<VonMises>(E, nu, m.cohesion);
        case YieldCriterion::mohr_coulomb:
          return std::make_unique<MohrCoulomb>(E,
                                               nu,
                                               m.cohesion,
                                               m.friction_angle * degree,
                                               m.dilation_angle * degree);
      }
    return nullptr;
  }
} // namespace thinlayer
