#include <thinlayer/materials/interface_law.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  namespace
  {
    /// |tau|, the shear part of a traction.
    double
    shear_magnitude(const Tensor<1, 3> &t)
    {
      // hypot: the squares of a traction of 1e155 overflow.
      return std::hypot(t[0], t[2]);
    }
  } // namespace


  InterfaceLaw::InterfaceLaw(const InterfaceElementParameters &p)
    : k_s(p.shear_stiffness)
    , k_n(p.normal_stiffness)
    , plastic(p.criterion != InterfaceElementParameters::Criterion::elastic)
    , adhesion(p.adhesion)
    , tan_phi(std::tan(p.friction_angle * numbers::PI / 180))
    , tan_psi(std::tan(p.dilation_angle * numbers::PI / 180))
    , tensile_strength(p.tensile_strength)
  {}


  Tensor<1, 3>
  InterfaceLaw::elastic_traction(const Tensor<1, 3> &delta) const
  {
    return Tensor<1, 3>({k_s * delta[0], k_n * delta[1], k_s * delta[2]});
  }


  Tensor<2, 3>
  InterfaceLaw::elasticity() const
  {
    Tensor<2, 3> K;
    K[0][0] = k_s;
    K[1][1] = k_n;
    K[2][2] = k_s;
    return K;
  }


  Tensor<2, 3>
  InterfaceLaw::compliance() const
  {
    Tensor<2, 3> C;
    C[0][0] = 1 / k_s;
    C[1][1] = 1 / k_n;
    C[2][2] = 1 / k_s;
    return C;
  }


  bool
  InterfaceLaw::can_yield() const
  {
    return plastic;
  }


  bool
  InterfaceLaw::is_associated() const
  {
    return !plastic || tan_phi == tan_psi;
  }


  double
  InterfaceLaw::yield_function(const Tensor<1, 3> &t) const
  {
    return std::max(shear_magnitude(t) + t[1] * tan_phi - adhesion,
                    t[1] - tensile_strength);
  }


  double
  InterfaceLaw::yield_ratio(const Tensor<1, 3> &t) const
  {
    return yield_function(t) / (adhesion > 0 ? adhesion : k_n);
  }


  double
  InterfaceLaw::mobilised_strength(const Tensor<1, 3> &t) const
  {
    if (!plastic)
      return 0;
    const double available = adhesion - t[1] * tan_phi;
    if (t[1] >= tensile_strength || available <= 0)
      return 1;
    return std::min(1., shear_magnitude(t) / available);
  }


  Tensor<1, 3>
  InterfaceLaw::flow_direction(const Tensor<1, 3> &t) const
  {
    Tensor<1, 3> direction;
    if (t[1] - tensile_strength >
        shear_magnitude(t) + t[1] * tan_phi - adhesion)
      {
        direction[1] = 1;
        return direction;
      }
    const double tau = shear_magnitude(t);
    if (tau > 0)
      {
        direction[0] = t[0] / tau;
        direction[2] = t[2] / tau;
      }
    direction[1] = tan_psi;
    return direction;
  }


  double
  InterfaceLaw::viscoplastic_time_step() const
  {
    return 1 / std::max(k_s, k_n * (1 + tan_phi * tan_psi));
  }


  InterfaceReturnMapping
  InterfaceLaw::return_mapping(const Tensor<1, 3> &trial,
                               const bool          with_tangent) const
  {
    InterfaceReturnMapping r{trial, elasticity(), InterfaceReturn::elastic};
    if (!plastic)
      return r;
    const double tau_trial = shear_magnitude(trial);
    const double f_slip    = tau_trial + trial[1] * tan_phi - adhesion;
    const double f_tension = trial[1] - tensile_strength;
    // A trial that is not a finite number stays as it is: its yield ratio
    // is not finite either, and the analysis fails the step on it.
    if (!std::isfinite(trial[0]) || !std::isfinite(trial[1]) ||
        !std::isfinite(trial[2]) || !std::isfinite(f_slip) ||
        (f_slip <= 0 && f_tension <= 0))
      return r;

    // The unit shear direction of the trial (none at tau = 0).
    Tensor<1, 3> m;
    if (tau_trial > 0)
      {
        m[0] = trial[0] / tau_trial;
        m[2] = trial[2] / tau_trial;
      }

    // Slip: t = trial - dlambda K dQ/dt, dlambda = f / H.
    if (f_slip > 0)
      {
        const double H       = k_s + k_n * tan_phi * tan_psi;
        const double dlambda = f_slip / H;
        // tau_trial - k_s dlambda, rearranged: the difference of two
        // large numbers loses c at a trial of 1e16 c (and gives 0).
        const double tau = (tau_trial * k_n * tan_phi * tan_psi +
                            k_s * (adhesion - trial[1] * tan_phi)) /
                           H;
        const double sigma = trial[1] - k_n * tan_psi * dlambda;
        if (tau >= 0 && sigma <= tensile_strength)
          {
            r.region      = InterfaceReturn::slip;
            r.traction[0] = tau * m[0];
            r.traction[2] = tau * m[2];
            r.traction[1] = sigma;
            if (with_tangent)
              {
                // d tau_vec/d delta_tau = k_s [I - (k_s/H) m m - (k_s
                // dlambda/|tau_trial|)(I - m m)] on the shear components.
                const double shrink = tau_trial > 0 ? tau / tau_trial : 0;
                r.tangent           = 0;
                for (const unsigned int i : {0u, 2u})
                  {
                    for (const unsigned int j : {0u, 2u})
                      r.tangent[i][j] =
                        k_s * (shrink * ((i == j ? 1. : 0.) - m[i] * m[j]) +
                               (1 - k_s / H) * m[i] * m[j]);
                    r.tangent[i][1] = -k_s * k_n * tan_phi / H * m[i];
                    r.tangent[1][i] = -k_n * tan_psi * k_s / H * m[i];
                  }
                r.tangent[1][1] = k_n * (1 - k_n * tan_psi * tan_phi / H);
              }
            return r;
          }
      }

    // Tension: sigma_n = T, the shear as it was, if that is admissible.
    if (f_tension > 0 && tau_trial + tensile_strength * tan_phi - adhesion <= 0)
      {
        r.region      = InterfaceReturn::tension;
        r.traction[1] = tensile_strength;
        if (with_tangent)
          {
            r.tangent       = 0;
            r.tangent[0][0] = k_s;
            r.tangent[2][2] = k_s;
          }
        return r;
      }

    // The corner: sigma_n = T and |tau| = c - T tan(phi) (zero at the
    // apex), along the trial's shear direction.
    r.region         = InterfaceReturn::corner;
    const double tau = std::max(adhesion - tensile_strength * tan_phi, 0.);
    r.traction[0]    = tau * m[0];
    r.traction[2]    = tau * m[2];
    r.traction[1]    = tensile_strength;
    if (with_tangent)
      {
        r.tangent = 0;
        if (tau_trial > 0)
          for (const unsigned int i : {0u, 2u})
            for (const unsigned int j : {0u, 2u})
              r.tangent[i][j] =
                k_s * tau / tau_trial * ((i == j ? 1. : 0.) - m[i] * m[j]);
      }
    return r;
  }
} // namespace thinlayer
