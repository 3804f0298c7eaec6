// Truths checked on one adaptive cycle (Adaptivity/Cycles = 1) of two
// small scenes, what refinement must keep of a thin layer and of interface
// elements:
// - Case 2's thin layer (t = 0.1 under and beside the footing, Tresca;
//   the soil elastic, so the plastic work, and the marking, is in the
//   layer): the refined mesh (cycle-1/mesh.msh) has layer cells of half
//   the thickness, and each is a quarter of a layer cell of the first
//   mesh (cycle-0/mesh.msh): half its length and half its thickness, so
//   the layer keeps its cells' aspect ratios, two rows of children;
// - the smooth pile section on interface elements (curved, 3 cells per
//   quarter circle): the refined cycle has more interface points than the
//   first (the refined cells' sides paired into child elements), and every
//   point of both cycles lies within 1e-3 of the contact circle
//   r = R + t = 1.02 (the quadratic mapping's own error on a side of 30
//   degrees is about 1.4e-4; a child's side on its parent's chord would
//   lie up to 0.035 off);
// - the 3D rough rigid footing and the rough footing by harmonic 0 run a
//   refined cycle each, with hanging nodes (in 3D on faces and edges).
// On two ranks (the .mpirun=2 output) every figure is the serial run's: a
// refined mesh split over the ranks has its curved sides on their curves
// and each rank the masters of its hanging nodes.
#include <deal.II/base/mpi.h>

#include <thinlayer/base/file_utilities.h>
#include <thinlayer/mesh/msh_file.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../common/parallel_truths.h"
#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  struct Extent
  {
    double thickness;
    double length;
    double x;
  };


  Extent
  extent_of(const std::vector<std::pair<double, double>> &corners)
  {
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const auto &[x, y] : corners)
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    return {y1 - y0, x1 - x0, x0};
  }


  // The extents of every cell of material @p material in gmsh's format 2.2
  // (the mesh as gmsh made it).
  std::vector<Extent>
  cells_of_gmsh(const std::string &file, const int material)
  {
    const thinlayer::MshFile    mesh(thinlayer::read_file(file), file);
    std::map<long, std::size_t> index;
    for (std::size_t k = 0; k < mesh.node_ids.size(); ++k)
      index[mesh.node_ids[k]] = k;
    std::vector<Extent> cells;
    for (const thinlayer::MshElement &element : mesh.elements)
      if (element.type == 3 && element.physical() == material)
        {
          std::vector<std::pair<double, double>> corners;
          for (const long node : element.nodes)
            corners.emplace_back(mesh.positions[index[node]][0],
                                 mesh.positions[index[node]][1]);
          cells.push_back(extent_of(corners));
        }
    return cells;
  }

  // The extents of every cell of material @p material in a mesh written by
  // deal.II's GridOut (gmsh's format 1: $NOD, then $ELM rows
  // "number type physical elementary n nodes...").
  std::vector<Extent>
  cells_of(const std::string &file, const int material)
  {
    std::ifstream                             in(file);
    std::map<long, std::pair<double, double>> nodes;
    std::vector<Extent>                       cells;
    std::string                               line;
    while (std::getline(in, line))
      if (line == "$NOD")
        {
          long n = 0;
          in >> n;
          for (long k = 0; k < n; ++k)
            {
              long   id;
              double x, y, z;
              in >> id >> x >> y >> z;
              nodes[id] = {x, y};
            }
        }
      else if (line == "$ELM")
        {
          long n = 0;
          in >> n;
          for (long k = 0; k < n; ++k)
            {
              long id, type, physical, elementary, count;
              in >> id >> type >> physical >> elementary >> count;
              std::vector<long> corner(count);
              for (auto &c : corner)
                in >> c;
              if (type != 3 || physical != material)
                continue;
              std::vector<std::pair<double, double>> corners;
              for (const long c : corner)
                corners.push_back(nodes[c]);
              cells.push_back(extent_of(corners));
            }
        }
    return cells;
  }

} // namespace


int
main(int argc, char **argv)
{
  // On two ranks (the .mpirun=2 output) each cycle's refined mesh is
  // partitioned afresh, an interface element's two cells kept together.
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  truths::print_on_rank_zero();
  using truths::expect;
  // Every rank reads the results once rank 0 has put them in place.
  const auto run = [](const std::string              &prm,
                      const std::vector<std::string> &settings) {
    // A run that fails leaves no results to read; the last run's are
    // removed once every rank has read them.
    MPI_Barrier(thinlayer::mpi::communicator());
    if (thinlayer::mpi::is_root())
      std::filesystem::remove_all("results");
    MPI_Barrier(thinlayer::mpi::communicator());
    run_results::run_prm(prm, settings);
    MPI_Barrier(thinlayer::mpi::communicator());
  };

  run("case2-strip-footing.prm",
      {"Mesh/Geometry parameters=half_width=1, width=5, depth=3, "
       "aspect_ratio=10, n_footing=4, n_side=4, n_depth=4, "
       "interface_beyond_footing=1",
       "Layers/Material ids=",
       "Adaptivity/Cycles=1",
       "Adaptivity/Stop tolerance=0"});
  // The refined mesh's coordinates are written to 12 digits.
  const double              tolerance = 1e-9;
  const std::vector<Extent> before =
    cells_of_gmsh("results/cycle-0/mesh.msh", 2);
  const std::vector<Extent> after    = cells_of("results/cycle-1/mesh.msh", 2);
  unsigned int              halved   = 0;
  bool                      quarters = !after.empty();
  for (const Extent &cell : after)
    if (std::abs(cell.thickness - 0.05) < tolerance)
      {
        ++halved;
        // Its parent: the first mesh's layer cell that holds it.
        bool found = false;
        for (const Extent &parent : before)
          if (cell.x >= parent.x - tolerance &&
              cell.x + cell.length <= parent.x + parent.length + tolerance)
            found = std::abs(parent.length - 2 * cell.length) < tolerance &&
                    std::abs(parent.thickness - 2 * cell.thickness) < tolerance;
        quarters = quarters && found;
      }
  std::printf("Case 2: %zu layer cells, then %zu, %u of them half as thick\n",
              before.size(),
              after.size(),
              halved);
  expect(halved > 0, "the refined cycle has layer cells half as thick");
  expect(quarters,
         "each is a quarter of a first-mesh layer cell: half its length, "
         "half its thickness (the aspect ratio kept)");

  run("circular-inclusion-zero-thickness.prm",
      {"Mesh/Geometry parameters=radius=1, thickness=0.02, outer=20, "
       "n_around=3, n_radial=6, growth=1.6, zero_thickness=1",
       "Adaptivity/Cycles=1",
       "Adaptivity/Stop tolerance=0"});
  std::vector<std::size_t> points;
  double                   off_circle = 0;
  for (const std::string cycle : {"results/cycle-0", "results/cycle-1"})
    {
      const auto rows =
        run_results::read_csv(run_results::newest_csv(cycle, "interface-4-"));
      points.push_back(rows.size());
      for (const auto &row : rows)
        off_circle =
          std::max(off_circle,
                   std::abs(std::hypot(row.at("x"), row.at("y")) - 1.02));
    }
  std::printf("pile section: %zu interface points, then %zu\n",
              points[0],
              points[1]);
  expect(points[1] > points[0], "the refined cycle has more interface points");
  std::printf("largest distance of an interface point from r = 1.02: "
              "%.1e\n",
              off_circle);
  expect(off_circle < 1e-3,
         "every interface point within 1e-3 of the circle r = 1.02");

  // The rough rigid footing's quarter body in 3D, one cycle on three steps
  // of its settlement: hanging faces and edges on a mesh split over the
  // ranks, whose hanging nodes' masters lie on other ranks' cells.
  run("circular-footing-rigid-3d.prm",
      {"Mesh/Geometry parameters=sector=90, footing=0, half_width=1, "
       "width=5, depth=3, n_around=2, n_footing=2, n_side=4, n_depth=4, "
       "growth=1",
       "Loading/Load increments=2, 2*2",
       "Adaptivity/Cycles=1",
       "Adaptivity/Marking fraction=0.6",
       "Adaptivity/Stop tolerance=0"});
  const auto cycles = run_results::summary("results")["adaptivity"]["cycles"];
  for (const auto &c : cycles)
    std::printf("3D footing, cycle %u: %u cells, %u DoFs, %s, load %.5g at "
                "the last settlement\n",
                c["cycle"].get<unsigned int>(),
                c["cells"].get<unsigned int>(),
                c["dofs"].get<unsigned int>(),
                c["outcome"].get<std::string>().c_str(),
                run_results::summary(
                  "results/cycle-" +
                  std::to_string(
                    c["cycle"].get<unsigned int>()))["last_converged_load"]
                  .get<double>());
  expect(cycles.size() == 2 && cycles[1]["cells"].get<unsigned int>() >
                                 cycles[0]["cells"].get<unsigned int>(),
         "the 3D cycle ran on its refined mesh, to the end of its steps");

  // The rough rigid footing by harmonic 0 (Fourier: the axis and the
  // harmonic's missing component constrained beside the hanging nodes),
  // one cycle on two steps of its settlement.
  run("circular-footing-rigid-settlement-adaptive.prm",
      {"Loading/Load increments=5, 5", "Adaptivity/Cycles=1"});
  const auto fourier = run_results::summary("results")["adaptivity"]["cycles"];
  for (const auto &c : fourier)
    std::printf("Fourier footing, cycle %u: %u cells, load %.5g at the last "
                "settlement\n",
                c["cycle"].get<unsigned int>(),
                c["cells"].get<unsigned int>(),
                run_results::summary(
                  "results/cycle-" +
                  std::to_string(
                    c["cycle"].get<unsigned int>()))["last_converged_load"]
                  .get<double>());
  expect(fourier.size() == 2 && fourier[1]["cells"].get<unsigned int>() >
                                  fourier[0]["cells"].get<unsigned int>(),
         "the Fourier cycle ran on its refined mesh, to the end of its steps");
  return truths::conclude();
}
