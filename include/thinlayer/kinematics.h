#ifndef thinlayer_kinematics_h
#define thinlayer_kinematics_h

#include <deal.II/base/symmetric_tensor.h>

namespace thinlayer
{
  using namespace dealii;

  /**
   * Plane strain: the 2D symmetric gradient embedded in a full 3D strain
   * with zero out-of-plane components. Strains and stresses are always
   * stored as 3D tensors so that one material law serves every kinematics
   * (plane strain, Fourier harmonics, 3D); sigma_zz is then kept for free.
   */
  inline SymmetricTensor<2, 3>
  plane_strain(const SymmetricTensor<2, 2> &strain_2d)
  {
    SymmetricTensor<2, 3> strain;
    strain[0][0] = strain_2d[0][0];
    strain[1][1] = strain_2d[1][1];
    strain[0][1] = strain_2d[0][1];
    return strain;
  }
} // namespace thinlayer

#endif
