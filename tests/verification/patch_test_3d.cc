// Truth checked: the patch test in 3D. A linear displacement field
// prescribed on the boundary of a unit cube of eight distorted hexahedra
// (meshes/patch-test-3d.msh: every node but the cube's corners moved, within
// the cube's faces and edges or inside it, so that no cell is a
// parallelepiped) must give the exact uniform stress at every Gauss point,
// to round-off, for the 20-node and 27-node elements and either quadrature.
// The exact stress is computed here from Lame's constants, independently of
// the code's elasticity tensor; so are the sums of reactions on the
// boundary, which must vanish (the patch is self-equilibrated), in x, y, z
// and as the moment about the z axis.
#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/postprocess/monitors.h>

#include <cstdio>

#include "../common/scene_test_utilities.h"
#include "../common/truths.h"

using namespace dealii;

int
main()
{
  // u = 1e-3 (x + 0.5 y - 0.3 z, 0.3 x - 0.2 y + 0.4 z, -0.1 x + 0.25 y +
  // 0.6 z).
  const double          E = 1000, nu = 0.25;
  const double          lambda     = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double          mu         = E / (2 * (1 + nu));
  const double          grad[3][3] = {{1, 0.5, -0.3},
                                      {0.3, -0.2, 0.4},
                                      {-0.1, 0.25, 0.6}};
  SymmetricTensor<2, 3> strain;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = i; j < 3; ++j)
      strain[i][j] = 1e-3 * (grad[i][j] + grad[j][i]) / 2;
  const SymmetricTensor<2, 3> exact =
    lambda * trace(strain) * unit_symmetric_tensor<3>() + 2 * mu * strain;
  std::printf("exact stress: xx %.6f yy %.6f zz %.6f xy %.6f xz %.6f yz "
              "%.6f\n",
              exact[0][0],
              exact[1][1],
              exact[2][2],
              exact[0][1],
              exact[0][2],
              exact[1][2]);

  for (const std::string element : {"Q20", "Q27"})
    for (const std::string gauss : {"2", "3"})
      {
        const std::string prm =
          "subsection Mesh\n"
          "  set File = " SOURCE_DIR "/../../meshes/patch-test-3d.msh\n"
          "end\n"
          "subsection Kinematics\n"
          "  set Type = 3d\n"
          "end\n"
          "subsection Discretisation\n"
          "  set Element = " +
          element +
          "\n"
          "  set Gauss points per direction = " +
          gauss +
          "\n"
          "end\n"
          "subsection Material 1\n"
          "  set Young's modulus = 1000\n"
          "  set Poisson's ratio = 0.25\n"
          "end\n"
          "subsection Boundary 1\n"
          "  set Constrained components = x, y, z\n"
          "  set Displacement = 1e-3*(x + 0.5*y - 0.3*z); "
          "1e-3*(0.3*x - 0.2*y + 0.4*z); 1e-3*(-0.1*x + 0.25*y + 0.6*z)\n"
          "end\n"
          "subsection Monitors\n"
          "  set Load measure = reaction\n"
          "  set Load boundary id = 1\n"
          "  set Displacement boundary id = 1\n"
          "end\n";
        double       max_error = 0, largest_reaction = 0;
        unsigned int n_cells = 0;
        thinlayer_tests::with_solved_step<3>(
          prm,
          "patch.prm",
          [&](const thinlayer::Analysis<3> &analysis,
              const thinlayer::Parameters  &p) {
            n_cells =
              analysis.get_dof_handler().get_triangulation().n_active_cells();
            for (unsigned int c = 0; c < n_cells; ++c)
              for (unsigned int q = 0; q < analysis.n_quadrature_points(); ++q)
                max_error =
                  std::max(max_error, (analysis.stress(c, q) - exact).norm());
            using Component = thinlayer::MonitorParameters::LoadComponent;
            for (const Component component : {Component::x,
                                              Component::y,
                                              Component::z,
                                              Component::moment,
                                              Component::torque})
              {
                thinlayer::MonitorParameters monitors = p.monitors;
                monitors.load_component               = component;
                largest_reaction =
                  std::max(largest_reaction,
                           std::abs(thinlayer::Monitors<3>(monitors,
                                                           analysis,
                                                           p.parameter_file)
                                      .load()));
              }
          });
        const double relative = max_error / exact.norm();
        std::printf("%s %sx%sx%s Gauss: %u cells\n",
                    element.c_str(),
                    gauss.c_str(),
                    gauss.c_str(),
                    gauss.c_str(),
                    n_cells);
        truths::expect(relative < 1e-12,
                       "max |sigma - exact|/|exact| below 1e-12");
        truths::expect(largest_reaction / exact.norm() < 1e-12,
                       "largest sum of reactions (x, y, z, moments about z "
                       "and y) / |exact| below 1e-12");
        if (!(relative < 1e-12))
          std::printf("  max relative stress error %.3e\n", relative);
      }
  return truths::conclude();
}
