#ifndef thinlayer_materials_mohr_coulomb_h
#define thinlayer_materials_mohr_coulomb_h

#include <thinlayer/materials/material_law.h>

namespace thinlayer
{
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
    can_yield() const override;

    /**
     * F = (s1 - s3)/2 + (s1 + s3)/2 sin(phi) - c cos(phi), the
     * invariant form sigma_m sin(phi) + sigma_bar (cos(theta)/sqrt(3) -
     * sin(theta) sin(phi)/3) - c cos(phi) written with the extreme
     * principal stresses. With no shear out of the x-y plane (plane
     * strain) they come from a 2x2 eigenproblem, with no asin, pow or
     * sincos: this is evaluated at every point in every viscoplastic
     * iteration.
     */
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

    bool
    is_associated() const override;

    /**
     * The return in principal-stress space (s1 >= s2 >= s3, as in de
     * Souza Neto, Peric and Owen, Computational Methods for Plasticity,
     * section 8.2), where the surface is made of planes
     *   F_13 = (s1 - s3)/2 + (s1 + s3)/2 sin(phi) - c cos(phi)
     * and its neighbours F_23, F_12, and the flow of plane ij is
     * (e_i - e_j)/2 + (e_i + e_j)/2 sin(psi). With perfect plasticity the
     * planes are linear in the principal stresses, so each candidate
     * return is a linear solve: first the main plane F_13; if that breaks
     * the ordering, the edge with F_23 (s1 = s2) or F_12 (s2 = s3); if
     * that gives a negative multiplier, the apex s = c cot(phi) (which
     * Tresca, phi = 0, does not have).
     */
    ReturnMapping
    return_mapping(const SymmetricTensor<2, 3> &trial,
                   const bool                   with_tangent) const override;

  private:
    const double cohesion;
    const double sin_phi;
    const double cos_phi;
    const double sin_psi;
  };
} // namespace thinlayer

#endif
