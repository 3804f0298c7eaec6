#ifndef thinlayer_materials_interface_law_h
#define thinlayer_materials_interface_law_h

#include <deal.II/base/tensor.h>

#include <thinlayer/parameters/interface_sections.h>

namespace thinlayer
{
  using namespace dealii;

  /// Where a traction return mapping ended.
  enum class InterfaceReturn
  {
    elastic,
    /// On the slip surface |tau| + sigma_n tan(phi) = c.
    slip,
    /// On the tension cut-off sigma_n = tensile strength.
    tension,
    /// At the corner of both (or the apex where they cross at tau = 0).
    corner
  };


  /// The result of InterfaceLaw::return_mapping().
  struct InterfaceReturnMapping
  {
    Tensor<1, 3>    traction;
    Tensor<2, 3>    tangent;
    InterfaceReturn region;
  };


  /**
   * The traction-separation law of a zero-thickness (Goodman-type)
   * interface, in the interface's local frame: component 0 along the
   * interface in the plane (s), 1 normal to it (n, opening and tension
   * positive), 2 along it out of the plane (t: z in plane strain, theta in
   * Fourier scenes). Elastic, t = K delta with K = diag(k_s, k_n, k_s);
   * perfectly plastic with the slip surface
   *   f = |tau| + sigma_n tan(phi) - c,   |tau| = sqrt(t_0^2 + t_2^2),
   * (Tresca: phi = 0), plastic potential |tau| + sigma_n tan(psi), and a
   * tension cut-off sigma_n <= T (T defaults to the apex c / tan(phi), or
   * none for Tresca). The return mapping is closed-form in each region and
   * its tangent consistent (unsymmetric where psi != phi).
   */
  class InterfaceLaw
  {
  public:
    explicit InterfaceLaw(const InterfaceElementParameters &parameters);

    /// K delta.
    Tensor<1, 3>
    elastic_traction(const Tensor<1, 3> &relative_displacement) const;

    /// K.
    Tensor<2, 3>
    elasticity() const;

    Tensor<2, 3>
    compliance() const;

    bool
    can_yield() const;

    bool
    is_associated() const;

    /// The larger of the slip and tension functions, in stress units.
    double
    yield_function(const Tensor<1, 3> &traction) const;

    /// The yield function over the adhesion (or the normal stiffness times
    /// a unit length where there is none): as the continuum laws' ratio.
    double
    yield_ratio(const Tensor<1, 3> &traction) const;

    /// The mobilised strength |tau| / (c - sigma_n tan(phi)) in [0, 1],
    /// as MaterialLaw::mobilised_strength(): 1 at or beyond the tension
    /// cut-off, 0 for an elastic law.
    double
    mobilised_strength(const Tensor<1, 3> &traction) const;

    /// dQ/dt of the active surface (the larger function) at @p traction.
    Tensor<1, 3>
    flow_direction(const Tensor<1, 3> &traction) const;

    /// A stable pseudo time step of the viscoplastic iterations for this
    /// law alone: 1 / max(k_s, k_n (1 + tan(phi) tan(psi))).
    double
    viscoplastic_time_step() const;

    /// The traction of the elastic trial @p trial returned to the
    /// admissible set, with the consistent tangent if @p with_tangent.
    InterfaceReturnMapping
    return_mapping(const Tensor<1, 3> &trial, const bool with_tangent) const;

  private:
    double k_s, k_n;
    bool   plastic;
    double adhesion, tan_phi, tan_psi;
    /// The tension cut-off (infinity where there is none).
    double tensile_strength;
  };
} // namespace thinlayer

#endif
