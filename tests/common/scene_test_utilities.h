#ifndef thinlayer_tests_scene_test_utilities_h
#define thinlayer_tests_scene_test_utilities_h

// What the tests that drive an Analysis directly share: a scene from the
// text of a parameter file, set up and solved in one step to load factor 1;
// and the elastic cylinder the Fourier tests use.

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/step_solver.h>

#include <iostream>
#include <string>

namespace thinlayer_tests
{
  /**
   * Read @p prm (as if from a file named @p name), build its scene and
   * analysis, solve one step to load factor 1, accept it, and hand the
   * analysis and its parameters to @p inspect while they live.
   */
  /**
   * An elastic cylinder (E = 1000, nu = 0.3) of radius 1 and height 2 as
   * the r-z plane of block.geo (3 x 4 cells; boundary ids 1 bottom, 2 the
   * mantle, 3 top, 4 the axis) under Fourier kinematics: the text of its
   * parameter file, with @p kinematics added to its Kinematics section,
   * the Boundary sections @p boundaries, and @p monitors added to its
   * Monitors section.
   */
  inline std::string
  elastic_cylinder(const std::string &kinematics,
                   const std::string &boundaries,
                   const std::string &monitors = "")
  {
    return "subsection Mesh\n"
           "  set File = " SOURCE_DIR "/../../meshes/block.geo\n"
           "  set Geometry parameters = width=1, height=2, nx=3, ny=4\n"
           "end\n"
           "subsection Kinematics\n"
           "  set Type = fourier\n"
           "  set Axis boundary id = 4\n" +
           kinematics +
           "end\n"
           "subsection Material 1\n"
           "  set Young's modulus = 1000\n"
           "  set Poisson's ratio = 0.3\n"
           "end\n" +
           boundaries +
           "subsection Monitors\n"
           "  set Displacement boundary id = 3\n" +
           monitors + "end\n";
  }


  template <int dim = 2, typename Inspect>
  void
  with_solved_step(const std::string &prm,
                   const std::string &name,
                   const Inspect     &inspect)
  {
    const thinlayer::Parameters p =
      thinlayer::ParameterReader().read_from_string(prm, name);
    const thinlayer::Scene<dim> scene(p, std::cout);
    thinlayer::Analysis<dim>    analysis(p, scene.triangulation());
    analysis.setup();
    {
      thinlayer::StepSolver<dim> solver(p.solver, analysis);
      solver.solve(1.0);
      solver.accept();
    }
    inspect(analysis, p);
  }
} // namespace thinlayer_tests

#endif
