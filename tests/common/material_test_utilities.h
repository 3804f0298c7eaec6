#ifndef thinlayer_tests_material_test_utilities_h
#define thinlayer_tests_material_test_utilities_h

// What the material-law tests share: a pseudo-random sequence that is the
// same on every machine, random stress states, and a material section in
// code (E = 1000, nu = 0.3).

#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/parameters/parameters.h>

namespace thinlayer_tests
{
  using namespace dealii;

  /// A linear congruential sequence in [0, 1).
  class PseudoRandom
  {
  public:
    explicit PseudoRandom(const unsigned long seed)
      : state(seed)
    {}

    double
    next()
    {
      state = state * 6364136223846793005UL + 1442695040888963407UL;
      return static_cast<double>(state >> 11) / static_cast<double>(1UL << 53);
    }

    /// A symmetric tensor with entries uniform in [-scale, scale].
    SymmetricTensor<2, 3>
    stress(const double scale)
    {
      SymmetricTensor<2, 3> s;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          s[i][j] = scale * (2 * next() - 1);
      return s;
    }

  private:
    unsigned long state;
  };

  inline thinlayer::MaterialParameters
  material(const thinlayer::YieldCriterion criterion,
           const double                    c,
           const double                    phi = 0,
           const double                    psi = 0)
  {
    return {"", 1000., 0.3, criterion, c, phi, psi};
  }
} // namespace thinlayer_tests

#endif
