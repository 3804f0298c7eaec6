#include <thinlayer/materials/elasticity.h>
#include <thinlayer/materials/von_mises.h>

#include <cmath>

namespace thinlayer
{
  bool
  VonMises::can_yield() const
  {
    return true;
  }


  double
  VonMises::yield_function(const SymmetricTensor<2, 3> &stress) const
  {
    return equivalent_stress(stress) - std::sqrt(3.) * cohesion;
  }


  SymmetricTensor<2, 3>
  VonMises::flow_direction(const SymmetricTensor<2, 3> &stress) const
  {
    return invariant_gradient(StressInvariants(stress), 0, 1, 0);
  }


  double
  VonMises::yield_ratio(const SymmetricTensor<2, 3> &stress) const
  {
    return yield_function(stress) / (std::sqrt(3.) * cohesion);
  }


  double
  VonMises::mobilised_strength(const SymmetricTensor<2, 3> &stress) const
  {
    return std::min(1., equivalent_stress(stress) / (std::sqrt(3.) * cohesion));
  }


  double
  VonMises::viscoplastic_time_step() const
  {
    return 4 * (1 + poissons_ratio) / (3 * youngs_modulus);
  }


  ReturnMapping
  VonMises::return_mapping(const SymmetricTensor<2, 3> &trial,
                           const bool                   with_tangent) const
  {
    // A trial that is not a finite number, or whose deviator's norm
    // overflows (which would return it to s = 0, a state on no
    // surface), stays as it is: its yield ratio is not finite, and the
    // analysis fails the step on it.
    // An elastic point, the most common, returns before the deviator
    // is formed.
    const double f = yield_function(trial);
    if (f <= 0 || !std::isfinite(f))
      return {trial, stiffness, ReturnRegion::elastic};
    const SymmetricTensor<2, 3> s    = deviator(trial);
    const double                norm = s.norm();
    if (!std::isfinite(norm))
      return {trial, stiffness, ReturnRegion::elastic};
    const SymmetricTensor<2, 3> n    = s / norm;
    const double                beta = std::sqrt(2.) * cohesion / norm;
    const double K = youngs_modulus / (3 * (1 - 2 * poissons_ratio));
    const double G = youngs_modulus / (2 * (1 + poissons_ratio));
    const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();
    if (!with_tangent)
      return {trace(trial) / 3 * I + beta * s, {}, ReturnRegion::surface};
    return {trace(trial) / 3 * I + beta * s,
            K * outer(I, I) +
              (2 * G * beta) * (deviator_tensor<3>() - outer(n, n)),
            ReturnRegion::surface};
  }
} // namespace thinlayer
