// Truth checked: the Fourier model and the 3D body it stands for agree. A
// rigid disc of radius 1 on an elastic cylinder of soil (radius 5, depth 3,
// E = 1000, nu = 0.3, base fixed, side held horizontally) is pushed down,
// sideways, rocked about a horizontal axis and twisted about its own; its
// four stiffnesses (force or moment per unit displacement or rotation)
// from the 3D half body (meshes/circular-footing-3d.geo, sector = 180:
// 20-node hexahedra, 1792 cells, the plane z = 0 held as the load's
// symmetry asks) and from Fourier harmonics on its r-z plane
// (meshes/prandtl.geo, 8-node quadrilaterals, 128 cells, the same radial
// and vertical spacing: vertical from harmonic 0, horizontal and rocking
// from harmonic 1, torsion from the antisymmetric harmonic 0) must agree
// within 1%. Each model discretises the body its own way (the 3D one with
// a core of hexahedra around the axis), so the two converge to one value
// from different sides; their difference is the discretisation's, not the
// kinematics'. Release only: 3D assembly under deal.II's debug library is
// too slow for the test suite.
#include <thinlayer/app/command_line.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /// The load of one run, from its summary.json.
  double
  load(const std::string &prm, const std::vector<std::string> &overrides)
  {
    std::ofstream("scene.prm") << prm;
    std::vector<std::string> arguments = {"scene.prm"};
    for (const std::string &o : overrides)
      arguments.insert(arguments.end(), {"-s", o});
    std::ostringstream out, err;
    if (thinlayer::run_command_line(arguments, out, err) != 0)
      std::cout << "run failed: " << err.str();
    std::ostringstream text;
    text << std::ifstream("results/summary.json").rdbuf();
    const std::string json = text.str();
    const auto        at   = json.find("\"last_converged_load\": ") + 23;
    return std::atof(json.c_str() + at);
  }

  const std::string body =
    "subsection Loading\n  set Load increments = 1\nend\n"
    "subsection Output\n  set Directory = results\n  set Write VTU = "
    "false\nend\n";

  /// The half body; the disc is boundary 1, the plane z = 0 boundary 5.
  const std::string solid =
    "subsection Mesh\n  set File = " SOURCE_DIR
    "/../../meshes/circular-footing-3d.geo\n  set Geometry parameters = "
    "sector=180, footing=0, half_width=1, width=5, depth=3, n_around=4, "
    "n_footing=4, n_side=8, n_depth=8, growth=1.2\nend\n"
    "subsection Kinematics\n  set Type = 3d\nend\n"
    "subsection Material 3\n  set Young's modulus = 1000\n  set Poisson's "
    "ratio = 0.3\nend\n"
    "subsection Boundary 1\n  set Constrained components = x, y, z\nend\n"
    "subsection Boundary 3\n  set Constrained components = x, y, z\nend\n"
    "subsection Boundary 4\n  set Constrained components = x, z\nend\n"
    "subsection Boundary 5\nend\n"
    "subsection Monitors\n  set Load measure = reaction\n  set Load "
    "boundary id = 1\n  set Load scale = 2\n  set Displacement boundary id "
    "= 1\nend\n" +
    body;

  /// The r-z plane; the disc is boundary 1, the axis 3. Cartesian
  /// displacements are x, y horizontal and z along the axis.
  const std::string fourier =
    "subsection Mesh\n  set File = " SOURCE_DIR
    "/../../meshes/prandtl.geo\n  set Geometry parameters = half_width=1, "
    "width=5, depth=3, n_footing=8, n_side=8, n_depth=8, growth=1.2\nend\n"
    "subsection Kinematics\n  set Type = fourier\n  set Axis boundary id = "
    "3\nend\n"
    "subsection Material 1\n  set Young's modulus = 1000\n  set Poisson's "
    "ratio = 0.3\nend\n"
    "subsection Boundary 1\n  set Constrained components = r, z, "
    "theta\nend\n"
    "subsection Boundary 4\n  set Constrained components = r, z, "
    "theta\nend\n"
    "subsection Boundary 5\n  set Constrained components = r, theta\nend\n"
    "subsection Monitors\n  set Load measure = reaction\n  set Load "
    "boundary id = 1\n  set Displacement boundary id = 1\nend\n" +
    body;

  struct Motion
  {
    const char              *name;
    std::vector<std::string> solid;
    std::vector<std::string> fourier;
  };
} // namespace


int
main()
{
  // The 3D frame has y up and the plane z = 0 as the half body's cut; the
  // Fourier one z up and theta from x towards y, a mirror image of the
  // first (x, z, y): moments change sign, so magnitudes are compared.
  const std::vector<Motion> motions = {
    {"vertical",
     {"Boundary 1/Displacement=0; -1; 0",
      "Boundary 5/Constrained components=z",
      "Monitors/Load component=y"},
     {"Kinematics/Harmonics=0",
      "Kinematics/Stations=0",
      "Boundary 1/Displacement=0; 0; -1",
      "Monitors/Load component=y"}},
    {"horizontal",
     {"Boundary 1/Displacement=1; 0; 0",
      "Boundary 5/Constrained components=z",
      "Monitors/Load component=x"},
     {"Kinematics/Harmonics=1",
      "Kinematics/Stations=0, 60, 120, 180",
      "Boundary 1/Displacement=1; 0; 0",
      "Monitors/Load component=x"}},
    {"rocking",
     {"Boundary 1/Displacement=0; x; 0",
      "Boundary 5/Constrained components=z",
      "Monitors/Load component=moment"},
     {"Kinematics/Harmonics=1",
      "Kinematics/Stations=0, 60, 120, 180",
      "Boundary 1/Displacement=0; 0; r*cos(theta)",
      "Monitors/Load component=moment"}},
    {"torsion",
     {"Boundary 1/Displacement=z; 0; -x",
      "Boundary 5/Constrained components=x, y",
      "Monitors/Load component=torque"},
     {"Kinematics/Harmonics=0",
      "Kinematics/Stations=0",
      "Kinematics/Series=antisymmetric",
      "Boundary 1/Displacement=-r*sin(theta); r*cos(theta); 0",
      "Monitors/Load component=torque"}}};
  for (const Motion &motion : motions)
    {
      const double k_solid    = std::abs(load(solid, motion.solid));
      const double k_fourier  = std::abs(load(fourier, motion.fourier));
      const double difference = k_solid / k_fourier - 1;
      std::printf("%-10s stiffness: 3D %.0f, Fourier %.0f, within 1%%: %s\n",
                  motion.name,
                  k_solid,
                  k_fourier,
                  std::abs(difference) < 0.01 ? "yes" : "NO");
    }
}
