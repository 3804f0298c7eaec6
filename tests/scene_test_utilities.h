#ifndef thinlayer_tests_scene_test_utilities_h
#define thinlayer_tests_scene_test_utilities_h

// What the tests that drive an Analysis directly share: a scene from the
// text of a parameter file, set up and solved in one step to load factor 1.

#include <thinlayer/analysis.h>
#include <thinlayer/parameters.h>
#include <thinlayer/scene.h>

#include <iostream>
#include <string>

namespace thinlayer_tests
{
  /**
   * Read @p prm (as if from a file named @p name), build its scene and
   * analysis, solve one step to load factor 1, accept it, and hand the
   * analysis and its parameters to @p inspect while they live.
   */
  template <typename Inspect>
  void
  with_solved_step(const std::string &prm,
                   const std::string &name,
                   const Inspect     &inspect)
  {
    const thinlayer::Parameters p =
      thinlayer::ParameterReader().read_from_string(prm, name);
    const thinlayer::Scene scene(p, std::cout);
    thinlayer::Analysis<2> analysis(p, scene.triangulation());
    analysis.setup();
    analysis.solve(1.0);
    analysis.accept_step();
    inspect(analysis, p);
  }
} // namespace thinlayer_tests

#endif
