// Truths checked for the pairing of facing cell sides along a split curve
// (pair_facing_sides()), on meshes/interface-patch.geo (nx = 4: the curve
// 3 runs along y = 0 from x = 0 to 1), split along curve 3:
// 1. 4 pairs on curve 3, one run, from the lower-left end: the arc lengths
//    0, 0.25, 0.5, 0.75, each side's entry at x = its arc length and its
//    exit 0.25 further along x (to 1e-9: gmsh's transfinite nodes are off
//    by up to about 1e-12); the plus cell (along the normal, the
//    tangent turned anticlockwise) above the curve, the minus cell below.
// 2. Refused with an InputError: a curve whose sides face none (the
//    bottom, curve 1) and a curve the mesh does not have (9).
#include <deal.II/fe/fe_q.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/gmsh_process.h>
#include <thinlayer/mesh/interface_pairing.h>
#include <thinlayer/mesh/mesh_splitting.h>
#include <thinlayer/mesh/msh_file.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  /// Whether pairing the curves @p curves throws an InputError.
  bool
  refused(const DoFHandler<2> &dof_handler, const types::boundary_id curve)
  {
    try
      {
        pair_facing_sides(dof_handler, {curve}, "pairing.prm");
      }
    catch (const InputError &e)
      {
        std::cout << "  curve " << curve << ": " << e.what() << '\n';
        return true;
      }
    return false;
  }
} // namespace


int
main()
{
  std::ostringstream progress;
  const std::string  text = run_gmsh(
    {SOURCE_DIR "/../../meshes/interface-patch.geo", {}, 1000, "pairing.prm"},
    progress);
  Triangulation<2> tria;
  create_triangulation(split_along_curves(MshFile(text, "interface-patch.geo"),
                                          {3}),
                       tria);
  const FE_Q<2> fe(1);
  DoFHandler<2> dof_handler(tria);
  dof_handler.distribute_dofs(fe);

  std::cout << "1. The pairs of curve 3\n";
  const auto pairs = pair_facing_sides(dof_handler, {3}, "pairing.prm");
  bool       along = pairs.size() == 4, sides = pairs.size() == 4;
  for (unsigned int k = 0; k < pairs.size(); ++k)
    {
      const FacingSides<2> &p = pairs[k];
      std::printf("  run %u, arc length %.4f, from (%.4f, %.4f) to (%.4f, "
                  "%.4f), plus cell at y = %.4f, minus cell at y = %.4f\n",
                  p.run,
                  p.arc_length,
                  p.entry[0],
                  p.entry[1],
                  p.exit[0],
                  p.exit[1],
                  p.plus_cell->center()[1],
                  p.minus_cell->center()[1]);
      along = along && p.curve == 3 && p.run == 0 &&
              std::abs(p.arc_length - 0.25 * k) < 1e-9 &&
              p.entry.distance(Point<2>(0.25 * k, 0)) < 1e-9 &&
              p.exit.distance(Point<2>(0.25 * (k + 1), 0)) < 1e-9;
      sides =
        sides && p.plus_cell->center()[1] > 0 && p.minus_cell->center()[1] < 0;
    }
  expect(along, "4 sides in one run from x = 0, 0.25 long each");
  expect(sides, "the plus cells above, the minus cells below");

  std::cout << "2. Refused\n";
  expect(refused(dof_handler, 1), "a curve whose sides face none");
  expect(refused(dof_handler, 9), "a curve the mesh does not have");
  return truths::conclude();
}
