// Truth checked: a 3D body held in plane strain is plane strain. Case 1
// (prm/case1-inclined-adhesive.prm, the column with an inclined Tresca
// slab) and the same column extruded along z (prm/case1-3d.prm: 20-node
// hexahedra, one element deep, u_z held on the faces z = 0 and z = depth)
// must give the same analysis: every load step's load (the 3D reaction per
// unit depth) and displacement, and at the last converged step the slab's
// slip, opening and tractions at each sample (the 3D samples at both depths
// against the 2D one at the same x, y), to a relative 1e-8. A 20-node
// hexahedron, integrated over its depth, is the 8-node quadrilateral: the
// plane-strain field is the 3D solution exactly, plastic points and all. A
// coarse mesh (4 elements along the slab and up each block) and the
// viscoplastic method, to collapse. The same for the column with
// zero-thickness interface elements (prm/case1-inclined-adhesive-zero-
// thickness.prm and prm/case1-3d-zero-thickness.prm: 6-node elements on the
// line, 16-node ones on the plane, the 3D samples at three depths).
#include <thinlayer/app/command_line.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  using run_results::read_csv;
  using run_results::Table;

  /// Runs @p prm with @p overrides into @p directory; whether it ran.
  bool
  run(const std::string              &prm,
      const std::vector<std::string> &overrides,
      const std::string              &directory)
  {
    std::vector<std::string> arguments = {std::string(SOURCE_DIR) +
                                          "/../../prm/" + prm};
    for (const std::string &o : overrides)
      arguments.insert(arguments.end(), {"-s", o});
    arguments.insert(
      arguments.end(),
      {"-s", "Output/Directory=" + directory, "-s", "Output/Write VTU=false"});
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line(arguments, out, err);
    if (status != 0)
      std::cout << prm << " failed: " << err.str();
    return status == 0;
  }

  double
  relative(const double a, const double b, const double scale)
  {
    return std::abs(a - b) / scale;
  }
} // namespace


namespace
{
  /**
   * Compare the plane-strain run of @p plane_prm with the extruded one of
   * @p extruded_prm (both on @p mesh, the viscoplastic method) and their
   * profiles @p profile (@p ratio 3D samples over each 2D one) at the last
   * converged step.
   */
  void
  compare(const std::string &title,
          const std::string &plane_prm,
          const std::string &extruded_prm,
          const std::string &mesh,
          const std::string &profile,
          const unsigned int ratio)
  {
    std::printf("%s\n", title.c_str());
    const std::string method = "Solver/Method=viscoplastic";
    if (!run(plane_prm, {mesh, method}, "plane") ||
        !run(extruded_prm,
             {mesh + ", depth=0.25, elements_depth=1", method},
             "extruded"))
      {
        truths::expect(false, "both runs ran");
        return;
      }

    const Table plane      = read_csv("plane/history.csv");
    const Table extruded   = read_csv("extruded/history.csv");
    double      load_scale = 0, displacement_scale = 0;
    for (const auto &row : plane)
      {
        load_scale = std::max(load_scale, std::abs(row.at("load")));
        displacement_scale =
          std::max(displacement_scale, std::abs(row.at("displacement")));
      }
    double       history_error  = 0;
    unsigned int last_converged = 0;
    bool         same_steps     = plane.size() == extruded.size();
    for (unsigned int k = 0; same_steps && k < plane.size(); ++k)
      {
        same_steps =
          same_steps &&
          plane[k].at("converged") == extruded[k].at("converged") &&
          plane[k].at("load_factor") == extruded[k].at("load_factor");
        history_error = std::max(
          {history_error,
           relative(plane[k].at("load"), extruded[k].at("load"), load_scale),
           relative(plane[k].at("displacement"),
                    extruded[k].at("displacement"),
                    displacement_scale)});
        if (plane[k].at("converged") == 1)
          last_converged = plane[k].at("step");
      }
    std::printf(" plane strain and extruded:\n");
    truths::expect(same_steps, "the same attempts, load factors and verdicts");
    truths::expect(std::isfinite(history_error) && history_error < 1e-8,
                   "loads and displacements agree to 1e-8 of their largest");

    // The interface at the last converged step.
    char step[16];
    std::snprintf(step, sizeof(step), "%04u", last_converged);
    const Table line =
      read_csv("plane/" + profile + "-" + std::string(step) + ".csv");
    const Table surface =
      read_csv("extruded/" + profile + "-" + std::string(step) + ".csv");
    const std::vector<std::pair<std::string, std::string>> fields = {
      {"slip", "slip_1"},
      {"opening", "opening"},
      {"shear_traction", "shear_traction_1"},
      {"normal_traction", "normal_traction"}};
    double       profile_error = 0, out_of_plane = 0, scale_slip = 0;
    unsigned int matched = 0;
    for (const auto &p : line)
      scale_slip = std::max(
        {scale_slip, std::abs(p.at("slip")), std::abs(p.at("opening"))});
    for (const auto &s : surface)
      for (const auto &p : line)
        if (std::abs(s.at("x") - p.at("x")) < 1e-9 &&
            std::abs(s.at("y") - p.at("y")) < 1e-9)
          {
            ++matched;
            for (const auto &[name_2d, name_3d] : fields)
              profile_error =
                std::max(profile_error,
                         relative(p.at(name_2d),
                                  s.at(name_3d),
                                  name_2d.find("traction") != std::string::npos
                                    ? 1.
                                    : // the adhesion
                                    scale_slip));
            out_of_plane = std::max({out_of_plane,
                                     std::abs(s.at("slip_2")) / scale_slip,
                                     std::abs(s.at("shear_traction_2"))});
          }
    std::printf(" the interface at the last converged step: %zu samples in "
                "2D, %zu on the surface\n",
                line.size(),
                surface.size());
    truths::expect(matched == surface.size() &&
                     surface.size() == ratio * line.size(),
                   "each surface sample over a 2D one");
    truths::expect(std::isfinite(profile_error) && profile_error < 1e-8,
                   "slip, opening and tractions agree to 1e-8 (of the largest "
                   "slip, of the adhesion)");
    truths::expect(std::isfinite(out_of_plane) && out_of_plane < 1e-8,
                   "slip and shear along z below 1e-8");
  }
} // namespace


int
main()
{
  const std::string mesh =
    "Mesh/Geometry parameters=alpha=45, aspect_ratio=10, elements_along=4, "
    "elements_block=4";
  compare("A slab of Tresca material (2x2 points per cell, 2x2 samples over "
          "each cell's face in 3D)",
          "case1-inclined-adhesive.prm",
          "case1-3d.prm",
          mesh,
          "layer-2",
          2);
  compare("Zero-thickness Tresca interface elements (3 Gauss points per "
          "side, 3x3 per face in 3D)",
          "case1-inclined-adhesive-zero-thickness.prm",
          "case1-3d-zero-thickness.prm",
          mesh + ", zero_thickness=1",
          "interface-3",
          3);
  return truths::conclude();
}
