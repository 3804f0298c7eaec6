// Truth checked: the collapse load is the limit of the load-displacement
// curve, not its knee, and the same whichever way the body is driven. A
// rough rigid footing on weightless Tresca soil (c = 1), by the default
// method, pushed by a pressure on its top (load control) and by a
// prescribed settlement of it (displacement control): a strip
// (prm/strip-footing-rigid-*.prm, plane strain; (2 + pi) c, a sharp curve)
// and a circular footing (prm/circular-footing-rigid-*.prm, Fourier
// harmonic 0; 6.05 c by Eason and Shield 1960, a curve that rounds off
// slowly), each on its file's coarse mesh. Asserted:
//  - under load the run ends in a collapse, under settlement it reaches a
//    plateau (a rise of at most the resolution, 0.5%, while the
//    displacement doubled);
//  - the two collapse loads agree within that resolution;
//  - the knee of the load-controlled curve (a step's secant stiffness below
//    0.01 of the elastic one) lies below the collapse by more than the
//    resolution: bracketing it, as the stepping did before, would have
//    reported a load that is not the limit;
//  - each collapse load lies above the classical value (the mesh is
//    coarse and a displacement method overestimates), and within 8% of it.
// Release only: under deal.II's debug library the four runs take minutes.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  struct Run
  {
    std::string outcome;
    double      collapse;
    double      knee;
    /// The file's Reference/Analytic load: the classical value.
    double reference;
  };

  /// The outcome, collapse load and knee of prm/@p name.prm.
  Run
  run(const std::string &name)
  {
    const std::string  directory = "results-" + name;
    std::ostringstream out, err;
    if (thinlayer::run_command_line({std::string(SOURCE_DIR) + "/../../prm/" +
                                       name + ".prm",
                                     "-s",
                                     "Output/Directory=" + directory,
                                     "-s",
                                     "Output/Write VTU=false"},
                                    out,
                                    err) != 0)
      std::cout << name << " failed: " << err.str();
    std::ostringstream text;
    text << std::ifstream(directory + "/summary.json").rdbuf();
    const std::string summary = text.str();
    const auto        at      = summary.find("\"outcome\": \"");
    const std::string outcome =
      at == std::string::npos
        ? ""
        : summary.substr(at + 12, summary.find('"', at + 12) - at - 12);
    return {outcome,
            run_results::summary_number(directory, "collapse_load"),
            run_results::summary_number(directory, "knee_load"),
            run_results::summary_number(directory, "reference_load")};
  }
} // namespace


int
main()
{
  using truths::expect;
  const double resolution = 0.005;
  for (const std::string name :
       {"strip-footing-rigid", "circular-footing-rigid"})
    {
      const Run    load       = run(name + "-load");
      const Run    settlement = run(name + "-settlement");
      const double classical  = load.reference;
      std::printf("%s: under load %s at %.3f c (knee %.3f c); under "
                  "settlement %s, plateau %.3f c; classical %.4f c\n",
                  name.c_str(),
                  load.outcome.c_str(),
                  load.collapse,
                  load.knee,
                  settlement.outcome.c_str(),
                  settlement.collapse,
                  classical);
      expect(std::isfinite(classical) && settlement.reference == classical,
             "both files state the classical value");
      expect(load.outcome == "collapse", "under load: a collapse");
      expect(settlement.outcome == "completed" &&
               std::isfinite(settlement.collapse),
             "under settlement: a plateau");
      expect(std::abs(load.collapse - settlement.collapse) <=
               resolution * std::max(load.collapse, settlement.collapse),
             "the two collapse loads agree within the resolution (0.5%)");
      expect(load.knee < (1 - resolution) * load.collapse,
             "the knee lies below the collapse by more than the resolution");
      for (const double collapse : {load.collapse, settlement.collapse})
        expect(collapse > classical && collapse < 1.08 * classical,
               "above the classical value, within 8% of it");
    }
  return truths::conclude();
}
