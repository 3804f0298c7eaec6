#ifndef thinlayer_materials_point_history_h
#define thinlayer_materials_point_history_h

#include <deal.II/base/symmetric_tensor.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * The state of the material at one Gauss point and one circumferential
   * station (plane strain has one station; a Fourier analysis one per
   * angle). Strains and stresses are 3D, tension positive.
   */
  struct PointState
  {
    /// Stress at the end of the last converged load step (sigma_0).
    SymmetricTensor<2, 3> converged_stress;
    /// Stress of the current iteration.
    SymmetricTensor<2, 3> stress;
    /// Plastic strain accumulated over converged load steps.
    SymmetricTensor<2, 3> plastic_strain;
    /// Viscoplastic strain of the current load step.
    SymmetricTensor<2, 3> step_plastic_strain;
    /// The part of step_plastic_strain that the stress does not account
    /// for yet: the paper's algorithm evaluates the stress and then adds
    /// the increment that stress calls for, so the last increment of a
    /// converged step has no stress of its own. Accepting the step leaves
    /// it out of the plastic strain, which then belongs to the accepted
    /// stress. Zero for the return-mapping methods.
    SymmetricTensor<2, 3> pending_plastic_strain;
    /// F > 0 at the last evaluation.
    bool yielding = false;
  };
} // namespace thinlayer

#endif
