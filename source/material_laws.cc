#include <thinlayer/elasticity.h>
#include <thinlayer/material_law.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thinlayer
{
  namespace
  {
    /**
     * Within this angle of a corner of the Tresca/Mohr-Coulomb hexagon
     * (|theta| = 30 degrees) the flow direction is the average of the two
     * faces that meet there, as Smith and Griffiths do: the exact gradient
     * has 1/cos(3 theta) in it.
     */
    const double corner_lode_angle = 29.0 * numbers::PI / 180.0;

    /**
     * dF/dsigma for F(sigma_m, sigma_bar, theta), from the partial
     * derivatives: d sigma_m = I/3, d sigma_bar = 3 s / (2 sigma_bar),
     * d theta = -tan(3 theta)/(2 J2) s - sqrt(3)/(2 cos(3 theta) J2^1.5)
     * (s.s - 2/3 J2 I).
     */
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
          gradient += dF_dlode * (-tan3 / (2 * inv.J2) * inv.deviator -
                                  std::sqrt(3.) /
                                    (2 * cos3 * std::pow(inv.J2, 1.5)) * dJ3);
        }
      return gradient;
    }


    /**
     * Elastic only: no yield surface.
     */
    class Elastic : public MaterialLaw
    {
    public:
      using MaterialLaw::MaterialLaw;
    };


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
      can_yield() const override
      {
        return true;
      }

      double
      yield_function(const SymmetricTensor<2, 3> &stress) const override
      {
        return equivalent_stress(stress) - std::sqrt(3.) * cohesion;
      }

      SymmetricTensor<2, 3>
      flow_direction(const SymmetricTensor<2, 3> &stress) const override
      {
        return invariant_gradient(StressInvariants(stress), 0, 1, 0);
      }

      double
      yield_ratio(const SymmetricTensor<2, 3> &stress) const override
      {
        return yield_function(stress) / (std::sqrt(3.) * cohesion);
      }

      double
      viscoplastic_time_step() const override
      {
        return 4 * (1 + poissons_ratio) / (3 * youngs_modulus);
      }

    private:
      const double cohesion;
    };


    /**
     * Mohr-Coulomb with cohesion c, friction angle phi and, for the plastic
     * potential, dilation angle psi:
     *   F = sigma_m sin(phi) + sigma_bar (cos(theta)/sqrt(3)
     *       - sin(theta) sin(phi)/3) - c cos(phi).
     * With phi = psi = 0 this is Tresca, F = (sigma_1 - sigma_3)/2 - c.
     */
    class MohrCoulomb : public MaterialLaw
    {
    public:
      MohrCoulomb(const double E,
                  const double nu,
                  const double cohesion,
                  const double friction_angle,
                  const double dilation_angle)
        : MaterialLaw(E, nu)
        , cohesion(cohesion)
        , sin_phi(std::sin(friction_angle))
        , cos_phi(std::cos(friction_angle))
        , sin_psi(std::sin(dilation_angle))
      {}

      bool
      can_yield() const override
      {
        return true;
      }

      double
      yield_function(const SymmetricTensor<2, 3> &stress) const override
      {
        const StressInvariants inv(stress);
        return inv.mean * sin_phi +
               inv.equivalent * (std::cos(inv.lode_angle) / std::sqrt(3.) -
                                 std::sin(inv.lode_angle) * sin_phi / 3) -
               cohesion * cos_phi;
      }

      SymmetricTensor<2, 3>
      flow_direction(const SymmetricTensor<2, 3> &stress) const override
      {
        // Q has the form of F with psi in place of phi (and no cohesion).
        const StressInvariants inv(stress);
        if (std::abs(inv.lode_angle) > corner_lode_angle)
          {
            // Corner: the average of the two faces' gradients, which is
            // the smooth gradient at theta = +-30 degrees without the
            // Lode-angle term.
            const double s = (inv.lode_angle > 0) ? 0.5 : -0.5;
            return invariant_gradient(inv, sin_psi, 0.5 - s * sin_psi / 3, 0);
          }
        const double c = std::cos(inv.lode_angle);
        const double s = std::sin(inv.lode_angle);
        return invariant_gradient(inv,
                                  sin_psi,
                                  c / std::sqrt(3.) - s * sin_psi / 3,
                                  inv.equivalent *
                                    (-s / std::sqrt(3.) - c * sin_psi / 3));
      }

      double
      yield_ratio(const SymmetricTensor<2, 3> &stress) const override
      {
        // The strength available at this mean stress; floored so that a
        // cohesionless point in tension reports a large ratio, not a
        // division by zero.
        const double available =
          cohesion * cos_phi - trace(stress) / 3 * sin_phi;
        return yield_function(stress) /
               std::max(available, 1e-12 * youngs_modulus);
      }

      double
      viscoplastic_time_step() const override
      {
        const double nu = poissons_ratio;
        return 4 * (1 + nu) * (1 - 2 * nu) /
               (youngs_modulus * (1 - 2 * nu + sin_phi * sin_phi));
      }

    private:
      const double cohesion;
      const double sin_phi;
      const double cos_phi;
      const double sin_psi;
    };
  } // namespace


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


  MaterialLaw::MaterialLaw(const double youngs_modulus,
                           const double poissons_ratio)
    : youngs_modulus(youngs_modulus)
    , poissons_ratio(poissons_ratio)
    , stiffness(isotropic_elasticity(youngs_modulus, poissons_ratio))
  {}


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
