// Truth checked: the resultants of reactions (and a stress average) in
// Fourier analyses, on a solid elastic cylinder of radius R = 1 and height
// H = 2 (the r-z plane of block.geo, its left side the axis):
// - axial compression by a prescribed top displacement delta (harmonic 0):
//   uniaxial stress, so the bottom's axial reaction is E pi R^2 delta / H
//   and the axial stress -E delta / H, exact for the element (the field is
//   linear);
// - a uniform horizontal traction 1 on the top, the bottom fixed (harmonic
//   1): by equilibrium the bottom's reactions are the force -pi R^2 along
//   theta = 0 and the overturning moment -pi R^2 H;
// - a torsional traction t_theta = r on the top (the antisymmetric harmonic
//   0): the bottom's torque is -pi R^4 / 2.
// Equilibrium of the discrete body makes the last two exact on any mesh;
// each is printed as the ratio to its closed form.
#include <thinlayer/analysis/analysis.h>
#include <thinlayer/mesh/scene.h>
#include <thinlayer/parameters/parameters.h>
#include <thinlayer/postprocess/monitors.h>

#include <cstdio>

#include "../common/scene_test_utilities.h"

namespace
{
  /// The load measure of the scene @p kinematics + @p boundaries +
  /// @p monitors after one elastic step to load factor 1.
  double
  measure(const std::string &kinematics,
          const std::string &boundaries,
          const std::string &monitors)
  {
    const std::string prm =
      thinlayer_tests::elastic_cylinder(kinematics, boundaries, monitors);
    double load = 0;
    thinlayer_tests::with_solved_step(
      prm,
      "fourier.prm",
      [&](const thinlayer::Analysis<2> &analysis,
          const thinlayer::Parameters  &p) {
        load =
          thinlayer::Monitors<2>(p.monitors, analysis, p.parameter_file).load();
      });
    return load;
  }

  void
  report(const char *what, const double value, const double exact)
  {
    std::printf("%s: computed / closed form = %.8f\n", what, value / exact);
  }
} // namespace


int
main()
{
  const double pi = 3.14159265358979323846, E = 1000, delta = 1e-3, H = 2;

  const std::string axial =
    "subsection Boundary 1\n  set Constrained components = z\nend\n"
    "subsection Boundary 3\n  set Constrained components = z\n"
    "  set Displacement = 0; 0; -1e-3\nend\n";
  const std::string harmonic_0 = "  set Harmonics = 0\n  set Stations = 0\n";
  report("axial reaction on the bottom, harmonic 0",
         measure(harmonic_0,
                 axial,
                 "  set Load measure = reaction\n  set Load boundary id = 1\n"
                 "  set Load component = y\n"),
         E * pi * delta / H);
  report("axial stress averaged over the r-z section, harmonic 0",
         measure(harmonic_0,
                 axial,
                 "  set Load measure = stress average\n"
                 "  set Load material id = 1\n"
                 "  set Load stress component = yy\n"),
         -E * delta / H);

  const std::string lateral =
    "subsection Boundary 1\n  set Constrained components = r, z, theta\nend\n"
    "subsection Boundary 3\n  set Traction = 1; 0; 0\nend\n";
  const std::string harmonic_1 =
    "  set Harmonics = 1\n  set Stations = 0, 90, 180\n";
  report("horizontal reaction on the bottom, harmonic 1",
         measure(harmonic_1,
                 lateral,
                 "  set Load measure = reaction\n  set Load boundary id = 1\n"
                 "  set Load component = x\n"),
         -pi);
  report("overturning moment of the bottom's reactions, harmonic 1",
         measure(harmonic_1,
                 lateral,
                 "  set Load measure = reaction\n  set Load boundary id = 1\n"
                 "  set Load component = moment\n"),
         -pi * H);

  report("torque on the bottom, antisymmetric harmonic 0",
         measure("  set Harmonics = 0\n  set Series = antisymmetric\n"
                 "  set Stations = 0\n",
                 "subsection Boundary 1\n  set Constrained components = r, "
                 "z, theta\nend\n"
                 "subsection Boundary 3\n  set Traction = -r*sin(theta); "
                 "r*cos(theta); 0\nend\n",
                 "  set Load measure = reaction\n  set Load boundary id = 1\n"
                 "  set Load component = torque\n"),
         -pi / 2);
}
