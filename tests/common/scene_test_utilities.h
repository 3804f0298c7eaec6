#ifndef thinlayer_tests_scene_test_utilities_h
#define thinlayer_tests_scene_test_utilities_h

// What the tests that drive an Analysis directly share: a scene from the
// text of a parameter file, set up and solved in one step to load factor 1;
// and the elastic cylinder the Fourier tests use.

#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameter_reader.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/stepping/step_solver.h>

#include <algorithm>
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
   * The patch tests' field u = 1e-3 (x + 0.5 y, 0.3 x - 0.2 y) (eps_xx =
   * 1e-3, eps_yy = -2e-4, eps_xy = 4e-4) in plane strain on a material of
   * E = 1000, nu = 0.25: its stress, from Lame's constants, independently
   * of the code's elasticity tensor.
   */
  inline dealii::SymmetricTensor<2, 3>
  patch_stress()
  {
    const double                  E = 1000, nu = 0.25;
    const double                  lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double                  mu     = E / (2 * (1 + nu));
    const double                  exx = 1e-3, eyy = -2e-4, exy = 4e-4;
    dealii::SymmetricTensor<2, 3> exact;
    exact[0][0] = lambda * (exx + eyy) + 2 * mu * exx;
    exact[1][1] = lambda * (exx + eyy) + 2 * mu * eyy;
    exact[2][2] = lambda * (exx + eyy);
    exact[0][1] = 2 * mu * exy;
    return exact;
  }


  /// The largest |sigma - @p reference| over every Gauss point of
  /// @p analysis.
  inline double
  largest_stress_difference(const thinlayer::Analysis<2>        &analysis,
                            const dealii::SymmetricTensor<2, 3> &reference)
  {
    const unsigned int n_cells =
      analysis.get_dof_handler().get_triangulation().n_active_cells();
    double largest = 0;
    for (unsigned int c = 0; c < n_cells; ++c)
      for (unsigned int q = 0; q < analysis.n_quadrature_points(); ++q)
        largest = std::max(largest, (analysis.stress(c, q) - reference).norm());
    return largest;
  }


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
