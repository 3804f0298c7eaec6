// Truth checked: plasticity under Fourier kinematics against classical
// limits. prm/circular-footing-rigid.prm, a rigid circular footing on
// weightless Tresca soil (harmonic 0), smooth and rough: the collapse
// pressure (the plateau of the footing's reaction per pi R^2 c) lies above
// the classical value, smooth 5.69 c (Shield 1955) and rough 6.05 c (Eason
// and Shield 1960), falls towards it as the mesh is refined, and is within
// 2% of it on the finest mesh. Two elements, both with 2x2 points: Q8, the
// default, on three meshes (240, 960 and 3840 cells), and Q9, which the
// file names, on the first two. Release only: deal.II's debug library
// makes it too long for the test suite.
#include <thinlayer/app/command_line.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"

namespace
{
  /// The collapse load (the plateau) of one run, from its summary.json.
  double
  collapse_load(const std::vector<std::string> &arguments)
  {
    std::ostringstream out, err;
    if (thinlayer::run_command_line(arguments, out, err) != 0)
      std::cout << "run failed: " << err.str();
    return run_results::summary_number("results", "collapse_load");
  }
} // namespace


int
main()
{
  const std::vector<std::string> meshes = {
    "half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=12, "
    "growth=1.15",
    "half_width=1, width=5, depth=3, n_footing=16, n_side=24, n_depth=24, "
    "growth=1.07",
    "half_width=1, width=5, depth=3, n_footing=32, n_side=48, n_depth=48, "
    "growth=1.035"};
  struct Element
  {
    const char  *name;
    unsigned int levels;
  };
  struct Footing
  {
    const char *name;
    const char *constrained;
    double      classical;
  };
  for (const Element element : {Element{"Q8", 3}, Element{"Q9", 2}})
    for (const Footing &footing :
         {Footing{"smooth", "z", 5.69}, Footing{"rough", "r, z", 6.05}})
      {
        std::vector<double> errors;
        for (unsigned int level = 0; level < element.levels; ++level)
          errors.push_back(
            collapse_load(
              {std::string(SOURCE_DIR) +
                 "/../../prm/circular-footing-rigid.prm",
               "-s",
               std::string("Discretisation/Element=") + element.name,
               "-s",
               "Mesh/Geometry parameters=" + meshes[level],
               "-s",
               std::string("Boundary 1/Constrained components=") +
                 footing.constrained,
               "-s",
               "Output/Directory=results",
               "-s",
               "Output/Write VTU=false"}) /
              footing.classical -
            1);
        bool above = true, falling = true;
        std::printf("%s, %s footing, %.2f c: errors",
                    element.name,
                    footing.name,
                    footing.classical);
        for (unsigned int level = 0; level < errors.size(); ++level)
          {
            std::printf(" %+.1f%%", 100 * errors[level]);
            above = above && errors[level] > 0;
            falling =
              falling && (level == 0 || errors[level] < errors[level - 1]);
          }
        std::printf("; above the classical value: %s; falling with "
                    "refinement: %s; within 2%% on the finest mesh: %s\n",
                    above ? "yes" : "NO",
                    falling ? "yes" : "NO",
                    std::abs(errors.back()) < 0.02 ? "yes" : "NO");
      }
}
