// Truth checked: plasticity under the body's own weight. The critical
// height of a vertical cut in Tresca clay (prm/vertical-cut.prm: H = 1,
// c = 1, the weight gamma raised by the load factor until the cut
// collapses, so the collapse load factor is gamma H_c / c). Pastor, Thai
// and Francescato (2000) bracket the exact value by limit analysis (the
// file's Reference/Analytic bracket, read back from summary.json). On two
// meshes (the file's 256 cells, then 1024, the elements halved), by the
// default method: each run ends in a collapse, its load lies above the
// bracket's lower end (a displacement mesh is too stiff), falls with
// refinement, and lies within 3% of the bracket's middle on the finer
// mesh. Release only: under deal.II's debug library the runs take
// minutes.
#include <thinlayer/app/command_line.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

int
main()
{
  using truths::expect;
  const std::vector<std::string> meshes = {
    "n_height=8, n_behind=12, n_front=8, n_depth=8, growth=1.1",
    "n_height=16, n_behind=24, n_front=16, n_depth=16, growth=1.05"};
  std::vector<double> loads;
  bool                collapsed = true;
  double              low = NAN, high = NAN;
  for (const std::string &mesh : meshes)
    {
      std::ostringstream out, err;
      if (thinlayer::run_command_line(
            {std::string(SOURCE_DIR) + "/../../prm/vertical-cut.prm",
             "-s",
             "Mesh/Geometry parameters=height=1, behind=3, front=2, "
             "depth=2, " +
               mesh,
             "-s",
             "Output/Directory=results",
             "-s",
             "Output/Write VTU=false"},
            out,
            err) != 0)
        std::printf("run failed: %s", err.str().c_str());
      loads.push_back(run_results::summary_number("results", "collapse_load"));
      const auto bracket =
        run_results::summary("results").value("reference_bracket",
                                              nlohmann::json::object());
      low       = bracket.value("low", NAN);
      high      = bracket.value("high", NAN);
      collapsed = collapsed && std::isfinite(loads.back());
    }
  const double middle = (low + high) / 2;
  std::printf("gamma H_c / c on 256 and 1024 cells: %.3f %.3f (Pastor et "
              "al. 2000: %.3f - %.3f)\n",
              loads[0],
              loads[1],
              low,
              high);
  expect(std::isfinite(middle), "the file states the bracket");
  expect(collapsed, "every mesh collapses");
  expect(loads[0] > low && loads[1] > low,
         "above the exact bracket's lower end");
  expect(loads[1] < loads[0], "falling with refinement");
  expect(std::abs(loads[1] / middle - 1) < 0.03,
         "within 3% of the bracket's middle on the finer mesh");
  return truths::conclude();
}
