// Truth checked: the revolved 3D view of a Fourier analysis
// (revolved_view()), on an elastic cylinder of radius 1 and height 2 (the
// r-z plane of block.geo), harmonic 1 of the symmetric series, stations
// 0, 90, 180 degrees, 8 slices:
// - a prescribed Cartesian translation (1e-3, 0, 0) of the whole boundary
//   moves the body rigidly: every vertex of every slice must show the
//   displacement (1e-3, 0, 0), which checks the sum over the harmonics at
//   the slices' angles and the turn from cylindrical to Cartesian
//   components; and every vertex lies at its cell vertex's radius and
//   height;
// - a uniform horizontal traction on the top (the bottom fixed) gives
//   stresses that are even in theta (rr, zz, tt, rz) or odd (rt, zt): the
//   slice mirrored about the plane theta = 0 must carry the same even
//   components and the opposite odd ones.
#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/output/revolved_view.h>
#include <thinlayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../common/scene_test_utilities.h"

namespace
{
  thinlayer::RevolvedView
  view_of(const std::string &boundaries, const unsigned int slices)
  {
    const std::string prm = thinlayer_tests::elastic_cylinder(
      "  set Harmonics = 1\n  set Stations = 0, 90, 180\n", boundaries);
    thinlayer::RevolvedView view;
    thinlayer_tests::with_solved_step(
      prm,
      "view.prm",
      [&](const thinlayer::Analysis<2> &analysis,
          const thinlayer::Parameters &) {
        view = thinlayer::revolved_view(analysis,
                                        thinlayer::CellFields(analysis),
                                        analysis.displacements(),
                                        slices);
      });
    return view;
  }
} // namespace


int
main()
{
  const unsigned int slices = 8, cells = 12;

  const thinlayer::RevolvedView rigid =
    view_of("subsection Boundary 1\n  set Constrained components = r, z, "
            "theta\n  set Displacement = 1e-3; 0; 0\nend\n"
            "subsection Boundary 2\n  set Constrained components = r, z, "
            "theta\n  set Displacement = 1e-3; 0; 0\nend\n"
            "subsection Boundary 3\n  set Constrained components = r, z, "
            "theta\n  set Displacement = 1e-3; 0; 0\nend\n",
            slices);
  double worst_displacement = 0, worst_position = 0;
  for (const auto &patch : rigid.patches)
    for (unsigned int v = 0; v < 8; ++v)
      {
        worst_displacement =
          std::max({worst_displacement,
                    std::abs(double(patch.data(0, v)) - 1e-3),
                    std::abs(double(patch.data(1, v))),
                    std::abs(double(patch.data(2, v)))});
        // The radius and height of a vertex match those of the vertex of
        // the same cell at the other end of the slice.
        const dealii::Point<3> &a = patch.vertices[v],
                               &b = patch.vertices[v ^ 4];
        worst_position =
          std::max({worst_position,
                    std::abs(std::hypot(a[0], a[1]) - std::hypot(b[0], b[1])),
                    std::abs(a[2] - b[2])});
      }
  std::printf("rigid translation: %zu patches (%u cells x %u slices); "
              "displacement (1e-3, 0, 0) at every vertex to 1e-9 (VTU data "
              "are floats): %s; "
              "vertices on their circles: %s\n",
              rigid.patches.size(),
              cells,
              slices,
              worst_displacement < 1e-9 ? "yes" : "NO",
              worst_position < 1e-12 ? "yes" : "NO");

  const thinlayer::RevolvedView lateral =
    view_of("subsection Boundary 1\n  set Constrained components = r, z, "
            "theta\nend\n"
            "subsection Boundary 3\n  set Traction = 1; 0; 0\nend\n",
            slices);
  double worst_even = 0, worst_odd = 0, largest = 0;
  for (unsigned int k = 0; k < slices; ++k)
    for (unsigned int c = 0; c < cells; ++c)
      {
        const auto &patch  = lateral.patches[k * cells + c];
        const auto &mirror = lateral.patches[(slices - 1 - k) * cells + c];
        for (unsigned int i = 3; i < 9; ++i)
          {
            const bool   odd = (i >= 7); // rt, zt
            const double difference =
              double(patch.data(i, 0)) - (odd ? -1. : 1.) * mirror.data(i, 0);
            (odd ? worst_odd : worst_even) =
              std::max(odd ? worst_odd : worst_even, std::abs(difference));
            largest = std::max(largest, std::abs(double(patch.data(i, 0))));
          }
      }
  std::printf("lateral traction: the mirrored slice has the same rr, zz, "
              "tt, rz: %s; the opposite rt, zt: %s; stresses not zero: %s\n",
              worst_even <= 1e-6 * largest ? "yes" : "NO",
              worst_odd <= 1e-6 * largest ? "yes" : "NO",
              largest > 0.1 ? "yes" : "NO");
}
