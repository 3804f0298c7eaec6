// Truth checked: the initial state and the phases after it. An elastic
// column of height H = 10, width W = 1, unit weight gamma = 20 under a
// surcharge q = 5, on a fixed base with its sides on rollers (an
// oedometric state), starts from the weight (Initial state), and is then
// loaded by a pressure p = 3 on its top (the loading phase). Both
// procedures reach the same state, to rounding (1e-10, relative):
//  - K0 procedure with K0 = nu / (1 - nu), the at-rest ratio of an elastic
//    oedometer: its stresses balance the weight and the surcharge (the
//    out-of-balance force is zero to rounding on these rectangles);
//  - gravity loading (the weight and the surcharge in two steps, a phase
//    of their own).
// After the loading: the base carries (gamma H + q + p) W (plane strain)
// or times pi W^2 / W (a Fourier cylinder of radius W, harmonic 0); the
// side carries K0 (gamma H^2 / 2 + (q + p) H) (plane strain); with Reset
// displacements the top settles by p H / M only (M the constrained
// modulus), and without it, after gravity loading, by (gamma H^2 / 2 +
// (q + p) H) / M. history.csv names the phase of every row. The same on
// two ranks, each holding part of the points the K0 procedure sets.
#include <deal.II/base/mpi.h>

#include <thinlayer/parallel/mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "../common/parallel_truths.h"
#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  const double gamma_w = 20, height = 10, q = 5, p = 3, E = 1e4, nu = 0.3;

  /// nu / (1 - nu) to every digit.
  std::string
  k0_text()
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", nu / (1 - nu));
    return text;
  }


  /// The column in @p kinematics, from @p procedure, measuring the
  /// reaction of @p boundary along @p component.
  std::string
  column(const std::string &kinematics,
         const std::string &procedure,
         const unsigned int boundary,
         const std::string &component,
         const bool         reset,
         const std::string &directory)
  {
    const bool  fourier = kinematics == "fourier";
    std::string prm =
      "subsection Mesh\n  set File = " + std::string(SOURCE_DIR) +
      "/../../meshes/block.geo\n  set Geometry parameters = width=1, "
      "height=10, nx=2, ny=10\nend\n";
    if (fourier)
      prm += "subsection Kinematics\n  set Type = fourier\n  set Harmonics "
             "= 0\n  set Stations = 0\n  set Axis boundary id = 4\nend\n";
    prm += "subsection Material 1\n  set Young's modulus = 1e4\n  set "
           "Poisson's ratio = 0.3\n  set Unit weight = 20\n  set K0 = " +
           k0_text() + "\nend\n";
    prm += "subsection Initial state\n  set Procedure = " + procedure +
           "\n  set Load increments = 0.5, 0.5\n  set Surcharge = 5\n  set "
           "Reset displacements = " +
           (reset ? "true" : "false") + "\nend\n";
    prm += std::string("subsection Boundary 1\n  set Constrained components "
                       "= ") +
           (fourier ? "r, z" : "x, y") + "\nend\n";
    prm += std::string("subsection Boundary 2\n  set Constrained components "
                       "= ") +
           (fourier ? "r" : "x") + "\nend\n";
    prm += "subsection Boundary 3\n  set Pressure = 3\nend\n";
    if (!fourier)
      prm += "subsection Boundary 4\n  set Constrained components = x\nend\n";
    prm += "subsection Loading\n  set Load increments = 1\nend\n"
           "subsection Monitors\n  set Load measure = reaction\n  set Load "
           "boundary id = " +
           std::to_string(boundary) + "\n  set Load component = " + component +
           "\n  set Displacement boundary id = 3\n  set Displacement "
           "component = y\nend\n"
           "subsection Output\n  set Directory = " +
           directory + "\n  set Write VTU = false\nend\n";
    return prm;
  }


  /// The phase column of history.csv, row by row.
  std::string
  phases(const std::string &directory)
  {
    std::ifstream in(directory + "/history.csv");
    std::string   line, result;
    std::getline(in, line);
    while (std::getline(in, line))
      result += (result.empty() ? "" : ", ") + line.substr(line.rfind(',') + 1);
    return result;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi_session(argc, argv, 1);
  // Every rank checks the same values; rank 0 prints.
  if (!truths::print_on_rank_zero())
    return 1;
  using truths::expect;
  const double M           = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double k0          = nu / (1 - nu);
  const double column_load = gamma_w * height * height / 2 + (q + p) * height;
  for (const std::string procedure : {"K0 procedure", "gravity loading"})
    {
      std::printf("%s:\n", procedure.c_str());
      struct Measure
      {
        const char  *kinematics;
        unsigned int boundary;
        const char  *component;
        double       truth;
        const char  *what;
      };
      for (const Measure m :
           {Measure{"plane-strain",
                    1,
                    "y",
                    gamma_w * height + q + p,
                    "the base carries the weight, the surcharge and p"},
            Measure{"plane-strain",
                    2,
                    "x",
                    -k0 * column_load,
                    "the side carries K0 times the vertical stresses"},
            Measure{"fourier",
                    1,
                    "y",
                    (gamma_w * height + q + p) * M_PI,
                    "the cylinder's base carries them"}})
        {
          const std::string directory = "results";
          const std::string failure   = run_results::run_text(column(
            m.kinematics, procedure, m.boundary, m.component, true, directory));
          const double      load =
            run_results::summary_number(directory, "last_converged_load");
          const double top =
            run_results::summary_number(directory, "final_displacement");
          std::printf("  %s, boundary %u along %s: %.10g (closed form "
                      "%.10g), top settles %.10g (p H / M = %.10g)\n",
                      m.kinematics,
                      m.boundary,
                      m.component,
                      load,
                      m.truth,
                      -top,
                      p * height / M);
          expect(failure.empty(), "the run succeeds");
          expect(std::abs(load / m.truth - 1) < 1e-10, m.what);
          expect(std::abs(-top / (p * height / M) - 1) < 1e-10,
                 "the loading's displacements start from zero");
          if (procedure == "K0 procedure")
            expect(run_results::summary_number(directory,
                                               "initial_out_of_balance") <
                     1e-10,
                   "the K0 stresses balance the weight and the surcharge");
          else
            expect(phases(directory) == "initial state, initial state, loading",
                   "history.csv names the phases: " + phases(directory));
        }
    }
  const std::string directory = "results-kept";
  const std::string failure   = run_results::run_text(
    column("plane-strain", "gravity loading", 1, "y", false, directory));
  const double top =
    -run_results::summary_number(directory, "final_displacement");
  std::printf("gravity loading, displacements kept: the top settles %.10g "
              "((gamma H^2 / 2 + (q + p) H) / M = %.10g)\n",
              top,
              column_load / M);
  expect(failure.empty(), "the run succeeds");
  expect(std::abs(top / (column_load / M) - 1) < 1e-10,
         "without a reset the weight's settlement is kept");
  return truths::conclude();
}
