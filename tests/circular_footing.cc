// Truth checked: plasticity under Fourier kinematics against classical
// limits. prm/circular-footing-rigid.prm, a rigid circular footing on
// weightless Tresca soil (harmonic 0, Q9 with 2x2 points), smooth and
// rough, on two meshes (240 and 960 cells): the collapse pressure (the
// plateau of the footing's reaction per pi R^2 c) lies above the classical
// value, smooth 5.69 c (Shield 1955) and rough 6.05 c (Eason and Shield
// 1960), falls towards it as the mesh is refined, and is within 2% of it
// on the finer mesh. Release only: about 10 s here, minutes with deal.II's
// debug library.
#include <thinlayer/command_line.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /// The collapse load (the plateau) of one run, from its summary.json.
  double
  collapse_load(const std::vector<std::string> &arguments)
  {
    std::ostringstream out, err;
    if (thinlayer::run_command_line(arguments, out, err) != 0)
      std::cout << "run failed: " << err.str();
    std::ostringstream text;
    text << std::ifstream("results/summary.json").rdbuf();
    const std::string json = text.str();
    const auto        at   = json.find("\"collapse_load\": ") + 17;
    return std::atof(json.c_str() + at);
  }
} // namespace


int
main()
{
  const char *meshes[] = {
    "half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=12, "
    "growth=1.15",
    "half_width=1, width=5, depth=3, n_footing=16, n_side=24, n_depth=24, "
    "growth=1.07"};
  struct Footing
  {
    const char *name;
    const char *constrained;
    double      classical;
  };
  for (const Footing &footing :
       {Footing{"smooth", "z", 5.69}, Footing{"rough", "r, z", 6.05}})
    {
      const double classical = footing.classical;
      double       loads[2];
      for (unsigned int level = 0; level < 2; ++level)
        loads[level] = collapse_load(
          {std::string(SOURCE_DIR) + "/../prm/circular-footing-rigid.prm",
           "-s",
           std::string("Mesh/Geometry parameters=") + meshes[level],
           "-s",
           std::string("Boundary 1/Constrained components=") +
             footing.constrained,
           "-s",
           "Output/Directory=results",
           "-s",
           "Output/Write VTU=false"});
      const double error_1 = loads[0] / classical - 1;
      const double error_2 = loads[1] / classical - 1;
      std::printf("%s footing, %.2f c: errors %+.1f%% and %+.1f%%; above "
                  "the classical value: %s; falling with refinement: %s; "
                  "within 2%% on the finer mesh: %s\n",
                  footing.name,
                  classical,
                  100 * error_1,
                  100 * error_2,
                  error_1 > 0 && error_2 > 0 ? "yes" : "NO",
                  error_2 < error_1 ? "yes" : "NO",
                  std::abs(error_2) < 0.02 ? "yes" : "NO");
    }
}
