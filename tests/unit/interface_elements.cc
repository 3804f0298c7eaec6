// Truths checked for zero-thickness interface elements
// (meshes/interface-patch.geo: two blocks of length L = 1, one on the
// other, joined along the physical curve 3, split when read):
// 1. Exact tractions and jumps. Under a uniform stress sigma_xy = tau,
//    sigma_yy = -p (tractions on the top and both sides; nu = 0, so that
//    the fixed base strains as the stress asks), every interface point
//    carries the traction (tau, -p) and the relative displacement
//    (tau / k_s, -p / k_n), for 2 and 3 Gauss points and Lobatto points.
//    Revolved (Fourier, harmonic 0, the blocks a ring from r = 1 to 2)
//    under sigma_zz = -p alone: traction (0, -p), opening -p / k_n.
// 2. Sliding at the exact load, by every solution method. With Tresca
//    (adhesion c = 1) the upper block slides when tau = c: the collapse
//    load factor is c / tau = 1. With Mohr-Coulomb (c = 0.1, phi = 30
//    degrees, psi = 0) it slides when tau = c + p tan(phi) at the same load
//    factor, lambda = c / (tau - p tan(phi)) = 0.23660. The bracket of
//    each run (last converged, first failed load factor) must contain the
//    value and be at most 1% wide.
// Run on 2 ranks (interface_elements.mpirun=2.output), where each rank
// holds the points of its own elements, the same truths hold for the
// profiles rank 0 writes; rank 0 prints.
#include <deal.II/base/mpi.h>

#include <thinlayer/app/command_line.h>
#include <thinlayer/elements/interface_values.h>
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

namespace
{
  const std::string patch = SOURCE_DIR "/../../meshes/interface-patch.geo";

  /// The patch under uniform shear tau and compression p (per unit load
  /// factor), with the interface section @p interface and @p extra.
  std::string
  scene(const std::string &interface, const std::string &extra)
  {
    return "subsection Mesh\n  set File = " + patch +
           "\nend\n"
           "subsection Material 1\n"
           "  set Young's modulus = 1000\n  set Poisson's ratio = 0\nend\n"
           "subsection Interface 3\n"
           "  set Normal stiffness = 1e5\n  set Shear stiffness = 4e4\n" +
           interface +
           "end\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Traction = 1; -1\nend\n"
           "subsection Boundary 4\n  set Traction = 0; -1\nend\n"
           "subsection Boundary 5\n  set Traction = 0; 1\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\n"
           "  set Displacement component = x\nend\n"
           "subsection Output\n  set Directory = results\n"
           "  set Write VTU = false\n  set Print timing = false\nend\n" +
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
        return false;
      }
    return true;
  }

  /// The rows of results/interface-3-NNNN.csv for step @p step.
  std::vector<std::vector<double>>
  profile(const unsigned int step)
  {
    char name[64];
    std::snprintf(name, sizeof(name), "results/interface-3-%04u.csv", step);
    std::ifstream                    in(name);
    std::string                      line;
    std::vector<std::vector<double>> rows;
    std::getline(in, line);
    while (std::getline(in, line))
      {
        std::vector<double> row;
        std::stringstream   fields(line);
        std::string         field;
        while (std::getline(fields, field, ','))
          row.push_back(field.empty() ? NAN : std::stod(field));
        rows.push_back(row);
      }
    return rows;
  }

  /// A number from results/summary.json.
  double
  summary(const std::string &key)
  {
    std::ostringstream text;
    text << std::ifstream("results/summary.json").rdbuf();
    const std::string json = text.str();
    const auto        at   = json.find("\"" + key + "\": ");
    return at == std::string::npos
             ? NAN
             : std::atof(json.c_str() + at + key.size() + 4);
  }

  /// Columns of the profile CSV.
  enum Column
  {
    slip            = 5,
    opening         = 7,
    shear_traction  = 10,
    normal_traction = 12
  };

  void
  check_exact(const std::string &title,
              const std::string &prm,
              const double       tau,
              const double       p)
  {
    std::cout << title << '\n';
    if (!run(prm))
      return;
    const auto   rows        = profile(1);
    const double exact[4][2] = {{slip, tau / 4e4},
                                {opening, -p / 1e5},
                                {shear_traction, tau},
                                {normal_traction, -p}};
    double       error       = 0;
    for (const auto &row : rows)
      for (const auto &[column, value] : exact)
        error = std::max(error,
                         std::abs(row[static_cast<int>(column)] - value) /
                           (value != 0 ? std::abs(value) : 1.));
    std::printf("  %zu points; traction (%g, %g) and jump (%g, %g) at every "
                "point: %s\n",
                rows.size(),
                tau,
                -p,
                tau / 4e4,
                -p / 1e5,
                error < 1e-8 ? "yes"
                             : ("NO, error " + std::to_string(error)).c_str());
  }

  void
  check_sliding(const std::string &title,
                const std::string &interface,
                const std::string &loading,
                const double       truth)
  {
    std::cout << title << ", exact " << truth << '\n';
    for (const std::string method : {"viscoplastic",
                                     "initial stress",
                                     "accelerated initial stress",
                                     "newton",
                                     "accelerated with newton fallback"})
      {
        if (!run(scene(interface, loading), {"-s", "Solver/Method=" + method}))
          continue;
        const double       low  = summary("last_converged_load");
        const double       high = summary("first_failed_load");
        std::ostringstream outcome;
        outcome << std::ifstream("results/summary.json").rdbuf();
        const bool collapse =
          outcome.str().find("\"outcome\": \"collapse\"") != std::string::npos;
        std::printf("  %-32s collapse: %s; bracket contains it: %s; at "
                    "most 1%% wide: %s\n",
                    method.c_str(),
                    collapse ? "yes" : "NO",
                    low <= truth && truth <= high ? "yes" : "NO",
                    high - low <= 0.01 * truth ? "yes" : "NO");
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  // Every rank reads the same files; rank 0 prints.
  if (!truths::print_on_rank_zero())
    return 1;
  const std::string elastic = "  set Slip criterion = elastic\n";
  const std::string one_step =
    "subsection Loading\n  set Load increments = 1\nend\n";
  check_exact("Uniform shear and compression, 3 Gauss points per side:",
              scene(elastic, one_step),
              1,
              1);
  check_exact("The same, 2 Gauss points per side:",
              scene(elastic + "  set Points per side = 2\n", one_step),
              1,
              1);
  check_exact("The same, Lobatto points:",
              scene(elastic + "  set Integration = lobatto\n", one_step),
              1,
              1);
  check_exact(
    "Fourier, harmonic 0, the blocks revolved as a ring, axial compression:",
    "subsection Mesh\n  set File = " + patch +
      "\n  set Geometry parameters = x0=1\nend\n"
      "subsection Kinematics\n  set Type = fourier\n  set Harmonics = 0\n"
      "  set Stations = 0\nend\n"
      "subsection Material 1\n"
      "  set Young's modulus = 1000\n  set Poisson's ratio = 0\nend\n"
      "subsection Interface 3\n"
      "  set Normal stiffness = 1e5\n  set Shear stiffness = 4e4\nend\n"
      "subsection Boundary 1\n  set Constrained components = r, z\nend\n"
      "subsection Boundary 2\n  set Traction = 0; 0; -1\nend\n"
      "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
      "subsection Output\n  set Directory = results\n"
      "  set Write VTU = false\n  set Print timing = false\nend\n" +
      one_step,
    0,
    1);

  check_sliding("Tresca sliding, c / tau",
                "  set Slip criterion = tresca\n  set Adhesion = 1\n",
                "subsection Loading\n  set Load increments = 0.5, "
                "20*0.047\nend\n",
                1.0);
  check_sliding("Mohr-Coulomb sliding, c / (tau - p tan(phi))",
                "  set Slip criterion = mohr-coulomb\n  set Adhesion = 0.1\n"
                "  set Friction angle = 30\n",
                "subsection Loading\n  set Load increments = 0.1, "
                "40*0.01\nend\n",
                0.1 / (1 - std::tan(M_PI / 6)));
}
