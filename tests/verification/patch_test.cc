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
  // u = 1e-3 (x + 0.5 y, 0.3 x - 0.2 y): eps_xx = 1e-3, eps_yy = -2e-4,
  // eps_xy = 4e-4.
  const double          E = 1000, nu = 0.25;
  const double          lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double          mu     = E / (2 * (1 + nu));
  const double          exx = 1e-3, eyy = -2e-4, exy = 4e-4;
  SymmetricTensor<2, 3> exact;
  exact[0][0] = lambda * (exx + eyy) + 2 * mu * exx;
  exact[1][1] = lambda * (exx + eyy) + 2 * mu * eyy;
  exact[2][2] = lambda * (exx + eyy);
  exact[0][1] = 2 * mu * exy;
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
            for (unsigned int c = 0; c < n_cells; ++c)
              for (unsigned int q = 0; q < analysis.n_quadrature_points(); ++q)
                max_error =
                  std::max(max_error, (analysis.stress(c, q) - exact).norm());
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
