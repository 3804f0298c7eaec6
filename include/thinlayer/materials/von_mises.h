#ifndef thinlayer_materials_von_mises_h
#define thinlayer_materials_von_mises_h

#include <thinlayer/materials/material_law.h>

namespace thinlayer
{
  /**
   * Von Mises, matched to Tresca in plane strain: F = sigma_bar - sqrt(3) c.
   */
  class VonMises : public MaterialLaw
  {
  public:
    VonMises(const double E, const double nu, const double cohesion)
      : MaterialLaw(E, nu)
      , cohesion(cohesion)
    {}

    bool
    can_yield() const override;

    double
    yield_function(const SymmetricTensor<2, 3> &stress) const override;

    SymmetricTensor<2, 3>
    flow_direction(const SymmetricTensor<2, 3> &stress) const override;

    double
    yield_ratio(const SymmetricTensor<2, 3> &stress) const override;

    double
    mobilised_strength(const SymmetricTensor<2, 3> &stress) const override;

    double
    viscoplastic_time_step() const override;

    /**
     * Radial return: the deviator is scaled back onto the cylinder,
     * s = sqrt(2) c s_trial / |s_trial|, the mean stress is kept; the
     * tangent is K I(x)I + 2G sqrt(2) c / |s_trial| (I_dev - n (x) n),
     * n = s_trial / |s_trial|.
     */
    ReturnMapping
    return_mapping(const SymmetricTensor<2, 3> &trial,
                   const bool                   with_tangent) const override;

  private:
    const double cohesion;
  };
} // namespace thinlayer

#endif
