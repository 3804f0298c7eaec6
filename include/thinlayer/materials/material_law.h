#ifndef thinlayer_materials_material_law_h
#define thinlayer_materials_material_law_h

#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/materials/stress_algebra.h>

#include <memory>

namespace thinlayer
{
  using namespace dealii;

  struct MaterialParameters;

  /**
   * Where a return mapping ended on the yield surface. For Mohr-Coulomb
   * and Tresca in principal-stress space (s1 >= s2 >= s3): the main plane
   * of s1 and s3, the edge where it meets the plane of s2 and s3 (s1 = s2),
   * the edge where it meets the plane of s1 and s2 (s2 = s3), or the apex;
   * von Mises has only its smooth surface.
   */
  enum class ReturnRegion
  {
    elastic,
    surface,
    edge_s1_equals_s2,
    edge_s2_equals_s3,
    apex
  };

  /**
   * The result of a return mapping: the admissible stress, the consistent
   * (algorithmic) tangent d stress / d strain, and where it ended.
   */
  struct ReturnMapping
  {
    SymmetricTensor<2, 3> stress;
    SymmetricTensor<4, 3> tangent;
    ReturnRegion          region;
  };

  /**
   * An elastic-perfectly plastic material at a point: isotropic elasticity,
   * and, for laws that can yield, a yield function F (F <= 0 is admissible,
   * in stress units), the direction of plastic flow dQ/dsigma, and the
   * stable pseudo time step of viscoplastic iterations.
   *
   * To add a law: derive from this class in a file of its own in
   * materials/ (von_mises.h, mohr_coulomb.h) and add one line to
   * create_material_law() in material_law.cc.
   */
  class MaterialLaw
  {
  public:
    MaterialLaw(const double youngs_modulus, const double poissons_ratio);

    virtual ~MaterialLaw() = default;

    const SymmetricTensor<4, 3> &
    elasticity() const;

    /**
     * elasticity() * @p strain, as lambda tr(strain) I + 2 mu strain: the
     * same stress in a fraction of the operations of the 6x6 product. The
     * viscoplastic iterations need it at every point, every iteration.
     */
    SymmetricTensor<2, 3>
    elastic_stress(const SymmetricTensor<2, 3> &strain) const
    {
      SymmetricTensor<2, 3> stress   = (2 * shear_modulus) * strain;
      const double          pressure = lame_lambda * trace(strain);
      for (unsigned int i = 0; i < 3; ++i)
        stress[i][i] += pressure;
      return stress;
    }

    /// Whether the law has a yield surface at all.
    virtual bool
    can_yield() const;

    /// F(sigma); <= 0 inside the yield surface.
    virtual double
    yield_function(const SymmetricTensor<2, 3> &stress) const;

    /// dQ/dsigma, the direction of plastic strain rate.
    virtual SymmetricTensor<2, 3>
    flow_direction(const SymmetricTensor<2, 3> &stress) const;

    /**
     * F divided by the strength available at this stress (c for Tresca,
     * sqrt(3) c for von Mises, c cos(phi) - sigma_m sin(phi) for
     * Mohr-Coulomb): 0 on the surface, > 0 outside. Its maximum after an
     * iteration has converged measures drift into illegal stress space.
     */
    virtual double
    yield_ratio(const SymmetricTensor<2, 3> &stress) const;

    /**
     * The mobilised strength tau_mob / tau_max in [0, 1] (PLAXIS's
     * relative shear stress): the shear stress in use over the shear
     * strength available at @p stress, 1 on the yield surface (and beyond
     * a cohesionless apex, where no shear strength is left), 0 for a law
     * that cannot yield, which has no strength to mobilise.
     */
    virtual double
    mobilised_strength(const SymmetricTensor<2, 3> &stress) const;

    /**
     * The largest pseudo time step for which viscoplastic strain
     * iterations are stable with this law (infinite if it cannot yield).
     */
    virtual double
    viscoplastic_time_step() const;

    /**
     * The closest-point (backward Euler) projection of the elastic trial
     * stress @p trial onto the yield surface, with the consistent tangent,
     * for the return-mapping solution methods (initial stress, Newton).
     * The tangent is the elasticity tensor where the trial stress is
     * admissible. Without @p with_tangent a plastic point's tangent is
     * left zero: the constant-stiffness methods do not use it, and in
     * principal-stress space it costs more than the return itself.
     */
    virtual ReturnMapping
    return_mapping(const SymmetricTensor<2, 3> &trial,
                   const bool                   with_tangent = true) const;

    /// Whether the flow rule is associated, i.e. the consistent tangent is
    /// symmetric (Newton can then use a Cholesky factorisation).
    virtual bool
    is_associated() const;

    /// The inverse of elasticity(): plastic strain from a stress excess.
    const SymmetricTensor<4, 3> &
    compliance() const;

  protected:
    const double                youngs_modulus;
    const double                poissons_ratio;
    const SymmetricTensor<4, 3> stiffness;
    const SymmetricTensor<4, 3> inverse_stiffness;
    /// The Lame constants of stiffness.
    const double lame_lambda;
    const double shear_modulus;
  };

  /**
   * Elastic only: no yield surface (what MaterialLaw itself does).
   */
  class Elastic : public MaterialLaw
  {
  public:
    using MaterialLaw::MaterialLaw;
  };

  /**
   * The law a material section asks for: elastic, tresca, von mises or
   * mohr-coulomb.
   */
  std::unique_ptr<MaterialLaw>
  create_material_law(const MaterialParameters &parameters);
} // namespace thinlayer

#endif
