// Truth checked: the weight of the body (Material <id>/Unit weight) as
// consistent nodal loads, in every kinematics. An elastic column of height
// H = 10 and unit weight gamma = 20 on a fixed base, its sides on rollers
// (a one-dimensional, oedometric state): sigma_yy = -gamma (H - y), linear,
// and the settlement u_y = -gamma (H y - y^2 / 2) / M, quadratic, with the
// constrained modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu)). Quadratic
// elements hold both exactly, so to rounding (1e-10, relative):
//  - the base's reaction is the weight: gamma W H per unit thickness in
//    plane strain (W = 1), gamma pi W^2 H for a Fourier cylinder of radius
//    W (harmonic 0, the axis on the left side), gamma W D H for a 3D box;
//  - the top settles by gamma H^2 / (2 M), uniformly.
// A Fourier body with the antisymmetric series has no harmonic 0 along the
// axis: its weight would load nothing, which is refused, naming the
// harmonic the weight needs.
#include <cmath>
#include <cstdio>
#include <string>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  const double gamma_w = 20, height = 10, E = 1e4, nu = 0.3;

  std::string
  mesh_dir()
  {
    return std::string(SOURCE_DIR) + "/../../meshes/";
  }

  /// The column: plane strain, Fourier or 3D.
  std::string
  column(const std::string &kind, const std::string &series = "symmetric")
  {
    const bool  solid = kind == "3d", fourier = kind == "fourier";
    std::string prm =
      "subsection Mesh\n  set File = " + mesh_dir() +
      (solid ? "box.geo\n  set Geometry parameters = width=1, height=10, "
               "depth=1, nx=2, ny=10, nz=2\n"
             : "block.geo\n  set Geometry parameters = width=1, height=10, "
               "nx=2, ny=10\n") +
      "end\n";
    if (solid)
      prm += "subsection Kinematics\n  set Type = 3d\nend\n";
    if (fourier)
      prm += "subsection Kinematics\n  set Type = fourier\n  set Harmonics "
             "= 0\n  set Series = " +
             series + "\n  set Stations = 0\n  set Axis boundary id = 4\nend\n";
    prm += "subsection Material 1\n  set Young's modulus = 1e4\n  set "
           "Poisson's ratio = 0.3\n  set Unit weight = 20\nend\n";
    prm += std::string("subsection Boundary 1\n  set Constrained components "
                       "= ") +
           (solid     ? "x, y, z"
            : fourier ? "r, z"
                      : "x, y") +
           "\nend\n";
    prm += std::string("subsection Boundary 2\n  set Constrained components "
                       "= ") +
           (fourier ? "r" : "x") + "\nend\n";
    if (!fourier)
      prm += "subsection Boundary 4\n  set Constrained components = x\nend\n";
    if (solid)
      prm += "subsection Boundary 5\n  set Constrained components = z\nend\n"
             "subsection Boundary 6\n  set Constrained components = z\nend\n";
    prm += "subsection Loading\n  set Load increments = 1\nend\n"
           "subsection Monitors\n  set Load measure = reaction\n  set Load "
           "boundary id = 1\n  set Load component = y\n  set Displacement "
           "boundary id = 3\n  set Displacement component = y\nend\n"
           "subsection Output\n  set Directory = results-" +
           kind + "\n  set Write VTU = false\nend\n";
    return prm;
  }
} // namespace


int
main()
{
  using truths::expect;
  const double M          = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double settlement = gamma_w * height * height / (2 * M);
  struct Kind
  {
    const char *name;
    double      weight;
  };
  for (const Kind kind : {Kind{"plane-strain", gamma_w * height},
                          Kind{"fourier", gamma_w * M_PI * height},
                          Kind{"3d", gamma_w * height}})
    {
      const std::string failure = run_results::run_text(column(kind.name));
      const std::string results = std::string("results-") + kind.name;
      const double      reaction =
        run_results::summary_number(results, "last_converged_load");
      const double top =
        run_results::summary_number(results, "final_displacement");
      std::printf("%s: base reaction %.10g (weight %.10g), top settlement "
                  "%.10g (gamma H^2 / (2 M) = %.10g)\n",
                  kind.name,
                  reaction,
                  kind.weight,
                  -top,
                  settlement);
      expect(failure.empty(), "the run succeeds");
      expect(std::abs(reaction / kind.weight - 1) < 1e-10,
             "the base carries the weight");
      expect(std::abs(-top / settlement - 1) < 1e-10,
             "the top settles by gamma H^2 / (2 M)");
    }
  // Measured by the load factor: the axial reaction is harmonic 0's too.
  std::string antisymmetric = column("fourier", "antisymmetric");
  antisymmetric.replace(antisymmetric.find("reaction\n"),
                        std::string("reaction\n  set Load boundary id = 1\n  "
                                    "set Load component = y\n")
                          .size(),
                        "load factor\n");
  const std::string refused = run_results::run_text(antisymmetric);
  std::printf("antisymmetric series: %s", refused.c_str());
  expect(refused.find("only harmonic 0 of the symmetric series carries it") !=
           std::string::npos,
         "the antisymmetric series' weight loads nothing: refused");
  return truths::conclude();
}
