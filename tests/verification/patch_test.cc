// Truth checked: the patch test. A linear displacement field prescribed on
// the boundary of the distorted five-element patch (meshes/patch-test.geo,
// meshed by gmsh through the scene) must give the exact uniform stress at
// every Gauss point, to round-off, for Q8 and Q9 and either quadrature. The
// exact stress is computed here from Lame's constants, independently of the
// code's elasticity tensor; so is the sum of reactions on the boundary,
// which must vanish (the patch is self-equilibrated).
#include <deal.II/base/symmetric_tensor.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/postprocess/monitors.h>

#include <cstdio>

#include "../common/scene_test_utilities.h"

using namespace dealii;

int
main()
{
  // u = 1e-3 (x + 0.5 y, 0.3 x - 0.2 y) on E = 1000, nu = 0.25.
  const SymmetricTensor<2, 3> exact = thinlayer_tests::patch_stress();
  std::printf("exact stress: xx %.6f yy %.6f zz %.6f xy %.6f\n",
              exact[0][0],
              exact[1][1],
              exact[2][2],
              exact[0][1]);

  for (const std::string element : {"Q8", "Q9"})
    for (const std::string gauss : {"2", "3"})
      {
        const std::string prm =
          "subsection Mesh\n"
          "  set File = " SOURCE_DIR "/../../meshes/patch-test.geo\n"
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
          "  set Constrained components = x, y\n"
          "  set Displacement = 1e-3*(x + 0.5*y); 1e-3*(0.3*x - 0.2*y)\n"
          "end\n"
          "subsection Monitors\n"
          "  set Load measure = reaction\n"
          "  set Load boundary id = 1\n"
          "  set Load component = x\n"
          "  set Displacement boundary id = 1\n"
          "end\n";
        double       max_error = 0, reaction = 0;
        unsigned int n_cells = 0;
        thinlayer_tests::with_solved_step(
          prm,
          "patch.prm",
          [&](const thinlayer::Analysis<2> &analysis,
              const thinlayer::Parameters  &p) {
            n_cells =
              analysis.get_dof_handler().get_triangulation().n_active_cells();
            max_error =
              thinlayer_tests::largest_stress_difference(analysis, exact);
            reaction =
              thinlayer::Monitors<2>(p.monitors, analysis, p.parameter_file)
                .load();
          });
        const double relative = max_error / exact.norm();
        std::printf("%s %sx%s Gauss: %u cells, max |sigma - exact|/|exact| "
                    "below 1e-12: %s; sum of x-reactions / |exact| below "
                    "1e-12: %s\n",
                    element.c_str(),
                    gauss.c_str(),
                    gauss.c_str(),
                    n_cells,
                    relative < 1e-12 ? "yes" : "NO",
                    std::abs(reaction) / exact.norm() < 1e-12 ? "yes" : "NO");
        if (relative >= 1e-12)
          std::printf("  max relative stress error %.3e\n", relative);
      }
}
