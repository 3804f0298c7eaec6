// Truth checked: the patch test on curved cells. meshes/circular-inclusion.geo
// at its coarsest (three cells along each quarter circle, radii 1, 1.3 and
// 3) is a half annulus whose cells follow its circles (Mesh/Curved cells,
// the quadratic mapping on a polar manifold), the circle r = 1.3 inside the
// body. A linear displacement prescribed on the whole boundary must give
// the exact uniform stress at every Gauss point, to round-off, for Q8 and
// Q9 and either quadrature: the cells' interior points are the
// transfinite interpolation of their curved sides, which for quadratic
// sides is the serendipity element's own centre, so a linear field lies in
// the Q8 space of a curved cell too. The exact stress is computed here from
// Lame's constants; an infinitesimal rigid rotation must give no stress at
// all. And the curved cells fill the half annulus: the sum of their Gauss
// weights is pi (3^2 - 1) / 2 to 1e-3 (the straight cells of the polygon
// miss 4.5% of it).
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameters.h>

#include <cmath>
#include <cstdio>

#include "../common/scene_test_utilities.h"

using namespace dealii;

namespace
{
  /// The scene: the coarse half annulus, every boundary prescribed
  /// @p displacement, curved or not.
  std::string
  scene(const std::string &element,
        const std::string &gauss,
        const std::string &displacement,
        const bool         curved)
  {
    std::string prm =
      "subsection Mesh\n"
      "  set File = " SOURCE_DIR "/../../meshes/circular-inclusion.geo\n"
      "  set Geometry parameters = radius=1, thickness=0.3, outer=3, "
      "n_around=3, n_radial=3, growth=1.5\n"
      "  set Curved cells = " +
      std::string(curved ? "true" : "false") +
      "\n"
      "end\n"
      "subsection Discretisation\n"
      "  set Element = " +
      element + "\n  set Gauss points per direction = " + gauss +
      "\n"
      "end\n";
    for (const char *id : {"1", "2"})
      prm += std::string("subsection Material ") + id +
             "\n"
             "  set Young's modulus = 1000\n"
             "  set Poisson's ratio = 0.25\n"
             "end\n";
    for (const char *id : {"1", "2", "3"})
      prm += std::string("subsection Boundary ") + id +
             "\n"
             "  set Constrained components = x, y\n"
             "  set Displacement = " +
             displacement + "\nend\n";
    return prm + "subsection Monitors\n"
                 "  set Displacement boundary id = 1\n"
                 "end\n";
  }


  /// The sum of the Gauss weights of the analysis's cells: their area.
  double
  area(const thinlayer::Analysis<2> &analysis)
  {
    const FE_Q<2>   linear(1);
    const QGauss<2> rule(3);
    FEValues<2> values(analysis.get_mapping(), linear, rule, update_JxW_values);
    double      sum = 0;
    for (const auto &cell :
         analysis.get_dof_handler().get_triangulation().active_cell_iterators())
      {
        values.reinit(cell);
        for (unsigned int q = 0; q < rule.size(); ++q)
          sum += values.JxW(q);
      }
    return sum;
  }
} // namespace


int
main()
{
  // u = 1e-3 (x + 0.5 y, 0.3 x - 0.2 y) on E = 1000, nu = 0.25.
  const SymmetricTensor<2, 3> exact      = thinlayer_tests::patch_stress();
  const double                exact_area = M_PI * (9 - 1) / 2;

  for (const std::string element : {"Q8", "Q9"})
    for (const std::string gauss : {"2", "3"})
      {
        double max_error = 0, max_rotation = 0, cell_area = 0;
        thinlayer_tests::with_solved_step(
          scene(element, gauss, "1e-3*(x + 0.5*y); 1e-3*(0.3*x - 0.2*y)", true),
          "curved.prm",
          [&](const thinlayer::Analysis<2> &analysis,
              const thinlayer::Parameters &) {
            max_error =
              thinlayer_tests::largest_stress_difference(analysis, exact);
            cell_area = area(analysis);
          });
        thinlayer_tests::with_solved_step(
          scene(element, gauss, "-1e-3*y; 1e-3*x", true),
          "rotation.prm",
          [&](const thinlayer::Analysis<2> &analysis,
              const thinlayer::Parameters &) {
            max_rotation = thinlayer_tests::largest_stress_difference(
              analysis, SymmetricTensor<2, 3>());
          });
        const double relative = max_error / exact.norm();
        std::printf("%s %sx%s Gauss: max |sigma - exact| / |exact| below "
                    "1e-10: %s; a rigid rotation's largest |sigma| / "
                    "|exact| below 1e-10: %s; the cells' area within 1e-3 of "
                    "the half annulus's: %s\n",
                    element.c_str(),
                    gauss.c_str(),
                    gauss.c_str(),
                    relative < 1e-10 ? "yes" : "NO",
                    max_rotation / exact.norm() < 1e-10 ? "yes" : "NO",
                    std::abs(cell_area / exact_area - 1) < 1e-3 ? "yes" : "NO");
        if (relative >= 1e-10 || max_rotation / exact.norm() >= 1e-10)
          std::printf("  max relative stress errors %.3e, %.3e\n",
                      relative,
                      max_rotation / exact.norm());
      }

  // The polygon, for contrast.
  double straight = 0;
  thinlayer_tests::with_solved_step(scene("Q8", "2", "1e-3*x; 0", false),
                                    "straight.prm",
                                    [&](const thinlayer::Analysis<2> &analysis,
                                        const thinlayer::Parameters &) {
                                      straight = area(analysis);
                                    });
  std::printf("straight cells: their area %.4f of the half annulus's\n",
              straight / exact_area);
}
