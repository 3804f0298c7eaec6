// Truths checked for zero-thickness interface elements in 3D
// (meshes/interface-patch-3d.geo with 2 x 1 x 2 elements in each: two
// blocks 1 x 0.5 x 1, one on the other, joined along the physical surface
// 3, y = 0, split when read; each element pairs two 8-node faces):
// 1. Exact tractions and jumps. Under a uniform stress sigma_xy = tau_x,
//    sigma_zy = tau_z, sigma_yy = -p (tractions on the top and the four
//    sides; nu = 0, so that the fixed base strains as the stress asks),
//    every interface point carries the traction (tau_x, -p, tau_z) in its
//    frame (t1 = x, n = y up, t2 = t1 x n = z) and the relative
//    displacement (tau_x / k_s, -p / k_n, tau_z / k_s), for 2 x 2 and
//    3 x 3 Gauss points and 3 x 3 Lobatto points. The points' weights
//    sum to the interface's area, 1 (the profile's patches tile it). The
//    top moves by the blocks' strain and the jump: (tau_x / G + tau_x /
//    k_s, -p / E - p / k_n, tau_z / G + tau_z / k_s).
// 2. Sliding at the exact load under a shear oblique to both tangents
//    (tau = (0.6, 0.8), |tau| = 1), by the paper's method and Newton (the
//    default method slides in 3. below and in scenes/case1_3d_zero_thickness).
//    With Tresca (adhesion c = 1) the upper block slides when |tau| = c: the
//    collapse load factor is 1. With Mohr-Coulomb (c = 0.1, phi = 30 degrees,
//    psi = 0, p = 1) when |tau| = c + p tan(phi): lambda = c / (|tau| - p
//    tan(phi)) = 0.23660. The bracket of each run (last converged, first failed
//    load factor) must contain the value and be at most 1% wide.
// 3. Sliding under a prescribed motion of the top, (0.6, 0, 0.8) per unit
//    load factor to 4 times the elastic limit, by the default method: every
//    point's shear traction lies on the slip circle |tau| = c (the return
//    mapping's, to 1e-9; its direction varies a little from point to point,
//    as the blocks tilt under the shear), the tractions recovered at the
//    nodes (the profile the run writes) are uniform at |tau| = c within 2%,
//    and the base's reaction along z
//    is -0.8 c A, A = 1 (to 1e-3, the iterations' tolerance).
// Run on 2 ranks (interface_elements_3d.mpirun=2.output), where each rank
// holds its own elements (both cells of each on one rank), the same truths
// hold; rank 0 prints.
#include <deal.II/base/mpi.h>

#include <thinlayer/app/command_line.h>
#include <thinlayer/parallel/mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/parallel_truths.h"
#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  const std::string patch = SOURCE_DIR "/../../meshes/interface-patch-3d.geo";
  /// Two elements along x and z, one up each block: 8 hexahedra, 4 faces
  /// on the interface.
  const std::string mesh = "  set Geometry parameters = nx=2, ny=1, nz=2\n";

  /// The patch under uniform shear (0.6, 0.8) and compression 1 (per unit
  /// load factor), with the interface section @p interface and @p extra.
  std::string
  scene(const std::string &interface,
        const std::string &extra,
        const bool         vtu = false)
  {
    return "subsection Mesh\n  set File = " + patch + "\n" + mesh +
           "end\n"
           "subsection Kinematics\n  set Type = 3d\nend\n"
           "subsection Material 1\n"
           "  set Young's modulus = 1000\n  set Poisson's ratio = 0\nend\n"
           "subsection Interface 3\n"
           "  set Normal stiffness = 1e5\n  set Shear stiffness = 4e4\n" +
           interface +
           "end\n"
           "subsection Boundary 1\n"
           "  set Constrained components = x, y, z\nend\n"
           "subsection Boundary 2\n  set Traction = 0.6; -1; 0.8\nend\n"
           "subsection Boundary 4\n  set Traction = 0; -0.6; 0\nend\n"
           "subsection Boundary 5\n  set Traction = 0; 0.6; 0\nend\n"
           "subsection Boundary 6\n  set Traction = 0; -0.8; 0\nend\n"
           "subsection Boundary 7\n  set Traction = 0; 0.8; 0\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\n"
           "  set Displacement component = x\nend\n"
           "subsection Output\n  set Directory = results\n"
           "  set Write VTU = " +
           (vtu ? "true" : "false") + "\n  set Print timing = false\nend\n" +
           extra;
  }

  /// Run @p prm; false (with the error) if the run failed.
  bool
  run(const std::string &prm, const std::vector<std::string> &options = {})
  {
    const std::string error = run_results::run_text(prm, options, "patch.prm");
    if (!error.empty())
      {
        std::cout << "  run failed: " << error;
        truths::failures += 1;
        return false;
      }
    return true;
  }

  /// The profile of step @p step: its tractions recovered at the nodes, or
  /// with @p gauss those of the points themselves.
  run_results::Table
  profile(const unsigned int step, const bool gauss = false)
  {
    char name[64];
    std::snprintf(name,
                  sizeof(name),
                  "results/interface-3-%s%04u.csv",
                  gauss ? "gauss-" : "",
                  step);
    return run_results::read_csv(name);
  }

  /// The area of the quadrilateral patch of a profile sample, from the
  /// VTU's points (four a cell, in order).
  double
  patch_area(const std::vector<std::vector<double>> &corners)
  {
    // Half the cross product of the diagonals (planar patches here).
    double d1[3], d2[3];
    for (unsigned int c = 0; c < 3; ++c)
      {
        d1[c] = corners[2][c] - corners[0][c];
        d2[c] = corners[3][c] - corners[1][c];
      }
    const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1],
                         d1[2] * d2[0] - d1[0] * d2[2],
                         d1[0] * d2[1] - d1[1] * d2[0]};
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }

  /// The sum of the patches' areas in results/interface-3-0001.vtu.
  double
  patches_area()
  {
    std::ifstream in("results/interface-3-0001.vtu");
    std::string   line;
    while (std::getline(in, line) && line.find("<Points>") == std::string::npos)
      ;
    std::getline(in, line); // the DataArray tag
    std::vector<std::vector<double>> corners;
    double                           area = 0;
    while (std::getline(in, line) &&
           line.find("</DataArray>") == std::string::npos)
      {
        std::istringstream  xyz(line);
        std::vector<double> x(3);
        xyz >> x[0] >> x[1] >> x[2];
        corners.push_back(x);
        if (corners.size() == 4)
          {
            area += patch_area(corners);
            corners.clear();
          }
      }
    return area;
  }

  void
  check_exact(const std::string &title,
              const std::string &interface,
              const unsigned int n_points)
  {
    std::cout << title << '\n';
    if (!run(scene("  set Slip criterion = elastic\n" + interface,
                   "subsection Loading\n  set Load increments = 1\nend\n",
                   true)))
      return;
    const auto                                        rows  = profile(1);
    const std::vector<std::pair<std::string, double>> exact = {
      {"slip_1", 0.6 / 4e4},
      {"opening", -1 / 1e5},
      {"slip_2", 0.8 / 4e4},
      {"shear_traction_1", 0.6},
      {"normal_traction", -1},
      {"shear_traction_2", 0.8},
      {"t1_x", 1},
      {"n_y", 1}};
    double error = 0;
    for (const auto &row : rows)
      for (const auto &[column, value] : exact)
        error =
          std::max(error, std::abs(row.at(column) - value) / std::abs(value));
    truths::expect(rows.size() == n_points,
                   std::to_string(rows.size()) + " points (" +
                     std::to_string(n_points) + " expected)");
    truths::expect(error < 1e-8,
                   "traction (0.6, -1, 0.8) and jump (1.5e-05, -1e-05, "
                   "2e-05) in the frame (x, y, z) at every point (to 1e-8)");
    truths::expect(std::abs(patches_area() - 1) < 1e-12,
                   "the points' patches tile the interface's area, 1");
    // The top, y = 0.5 above the fixed base y = -0.5: the blocks' shear
    // strain tau / G (G = E / 2 with nu = 0) and the interface's jump.
    const double top[3] = {0.6 / 500 + 0.6 / 4e4,
                           -1. / 1000 - 1 / 1e5,
                           0.8 / 500 + 0.8 / 4e4};
    double       worst  = 0;
    unsigned int n_top  = 0;
    for (const auto &row : run_results::read_csv("results/displacements.csv"))
      if (std::abs(row.at("y") - 0.5) < 1e-12)
        {
          ++n_top;
          worst = std::max({worst,
                            std::abs(row.at("u_x") - top[0]),
                            std::abs(row.at("u_y") - top[1]),
                            std::abs(row.at("u_z") - top[2])});
        }
    truths::expect(n_top > 0 && worst < 1e-12,
                   "the top's displacement (1.215e-03, -1.01e-03, 1.62e-03) "
                   "at every vertex of it (to 1e-12)");
  }

  void
  check_sliding(const std::string &title,
                const std::string &interface,
                const std::string &loading,
                const double       truth)
  {
    std::cout << title << ", exact " << truth << '\n';
    for (const std::string method : {"viscoplastic", "newton"})
      {
        std::cout << " " << method << '\n';
        if (!run(scene(interface, loading), {"-s", "Solver/Method=" + method}))
          continue;
        const double low =
          run_results::summary_number("results", "last_converged_load");
        const double high =
          run_results::summary_number("results", "first_failed_load");
        std::ostringstream outcome;
        outcome << std::ifstream("results/summary.json").rdbuf();
        truths::expect(outcome.str().find("\"outcome\": \"collapse\"") !=
                         std::string::npos,
                       "collapse");
        truths::expect(low <= truth && truth <= high,
                       "the bracket contains it");
        truths::expect(high - low <= 0.01 * truth, "at most 1% wide");
      }
  }

  void
  check_prescribed_sliding()
  {
    std::cout << "Tresca sliding under a prescribed motion (0.6, 0, 0.8) of "
                 "the top\n";
    const std::string prm =
      "subsection Mesh\n  set File = " + patch + "\n" + mesh +
      "end\n"
      "subsection Kinematics\n  set Type = 3d\nend\n"
      "subsection Material 1\n"
      "  set Young's modulus = 1000\n  set Poisson's ratio = 0\nend\n"
      "subsection Interface 3\n"
      "  set Normal stiffness = 1e5\n  set Shear stiffness = 4e4\n"
      "  set Slip criterion = tresca\n  set Adhesion = 1\nend\n"
      "subsection Boundary 1\n"
      "  set Constrained components = x, y, z\nend\n"
      "subsection Boundary 2\n  set Constrained components = x, z\n"
      "  set Displacement = 0.6e-3; 0; 0.8e-3\nend\n"
      "subsection Loading\n  set Load increments = 10*1\nend\n"
      "subsection Monitors\n  set Load measure = reaction\n"
      "  set Load boundary id = 1\n  set Load component = z\n"
      "  set Displacement boundary id = 2\n"
      "  set Displacement component = z\nend\n"
      "subsection Output\n  set Directory = results\n"
      "  set Write VTU = false\n  set Print timing = false\n"
      "  set Gauss-point profiles = true\nend\n";
    if (!run(prm))
      return;
    const auto history = run_results::read_csv("results/history.csv");
    truths::expect(history.size() == 10 && history.back().at("converged") == 1,
                   "all 10 steps converged (the default method)");
    // The largest distance of the profile's |tau| from c.
    const auto off_circle = [](const run_results::Table &rows) {
      double off = rows.empty() ? 1. : 0.;
      for (const auto &row : rows)
        off = std::max(off,
                       std::abs(std::hypot(row.at("shear_traction_1"),
                                           row.at("shear_traction_2")) -
                                1));
      return off;
    };
    truths::expect(off_circle(profile(history.size(), true)) < 1e-9,
                   "every point's shear traction on the slip circle, "
                   "|tau| = c (to 1e-9)");
    truths::expect(off_circle(profile(history.size())) < 0.02,
                   "the recovered shear traction uniform at c (2%)");
    truths::expect(std::abs(history.back().at("load") + 0.8) < 1e-3,
                   "the base's reaction along z -0.8 c A (to 1e-3, the "
                   "iterations' tolerance)");
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  // Every rank reads the same files; rank 0 prints.
  if (!truths::print_on_rank_zero())
    return 1;
  check_exact(
    "Uniform shear and compression, 3 x 3 Gauss points per face:", "", 4 * 9);
  check_exact("The same, 2 x 2 Gauss points per face:",
              "  set Points per side = 2\n",
              4 * 4);
  check_exact(
    "The same, 3 x 3 Lobatto points:", "  set Integration = lobatto\n", 4 * 9);

  check_sliding("Tresca sliding, c / |tau|",
                "  set Slip criterion = tresca\n  set Adhesion = 1\n",
                "subsection Loading\n  set Load increments = 0.9, "
                "5*0.047\nend\n",
                1.0);
  check_sliding("Mohr-Coulomb sliding, c / (|tau| - p tan(phi))",
                "  set Slip criterion = mohr-coulomb\n  set Adhesion = 0.1\n"
                "  set Friction angle = 30\n",
                "subsection Loading\n  set Load increments = 0.2, "
                "10*0.007\nend\n",
                0.1 / (1 - std::tan(M_PI / 6)));
  check_prescribed_sliding();
  return truths::conclude();
}
