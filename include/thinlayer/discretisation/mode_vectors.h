#ifndef thinlayer_discretisation_mode_vectors_h
#define thinlayer_discretisation_mode_vectors_h

#include <deal.II/lac/vector.h>

#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /**
   * One vector per mode (one in plane strain, one per Fourier harmonic),
   * each over the DoFs of the one DoFHandler: displacements, forces and
   * loads, the currency between the analysis, its element groups and the
   * solution methods. Each holder says what its vectors mean; the type
   * says only how they are laid out.
   */
  using ModeVectors = std::vector<Vector<double>>;
} // namespace thinlayer

#endif
