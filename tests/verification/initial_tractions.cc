// Truth checked: zero-thickness interface elements start from the K0
// procedure's stresses. A block of width 2 and height H = 1 (unit weight
// gamma = 20, elastic, E = 1e4, nu = 0.3) on a fixed base with its sides
// on rollers is crossed by an interface (Mohr-Coulomb, phi = 30, k = 1e8) from
// side to side:
//  - inclined (from y = 0.3 to y = 0.7), the same K0 = 0.6 on both sides:
//    each point starts from the traction sigma n of the at-rest stresses,
//    shear included ((sigma_v - sigma_h) sin(a) cos(a)), and the whole
//    balances the weight: the out-of-balance force is zero to rounding
//    (1e-10 of the largest nodal weight; with the shear's sign turned it
//    is not);
//  - horizontal (y = 0.5), K0 = 0.5 below and 0.7 above: sigma_v is the
//    same on both sides, so the field balances (1e-10), and after a
//    pressure p = 10 on the top the interface carries
//    sigma_n = -(gamma (H - y) + p) and no shear, to 1e-8 (the oedometric
//    state, in which the interface's jump moves the upper block bodily).
// Refused, naming the entry (a side's Material <id>/K0, the Interface
// curve's Friction angle): K0s that differ across the inclined
// interface (the tractions of the two sides differ), and an interface too
// weak for the at-rest shear (phi = 2 degrees: |tau| / sigma_n = 0.081
// above tan(2) = 0.035).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/run_results.h"
#include "../common/truths.h"

namespace
{
  const double gamma_w = 20, p = 10;

  /// The block, its interface from (0, @p left) to (2, @p right): surfaces
  /// 1 (below) and 2 (above), curves 1 bottom, 2 right, 3 top, 4 left,
  /// 5 the interface.
  void
  write_mesh(const double left, const double right)
  {
    std::ofstream("block.geo")
      << "Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0};\n"
      << "Point(3) = {2, " << right << ", 0}; Point(4) = {0, " << left
      << ", 0};\n"
      << "Point(5) = {2, 1, 0}; Point(6) = {0, 1, 0};\n"
      << "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; "
         "Line(4) = {4, 1};\n"
      << "Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};\n"
      << "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
      << "Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};\n"
      << "Transfinite Curve{1, 3, 6} = 9; Transfinite Curve{2, 4, 5, 7} = 4;\n"
      << "Transfinite Surface{1, 2}; Recombine Surface{1, 2};\n"
      << "Physical Surface(1) = {1}; Physical Surface(2) = {2};\n"
      << "Physical Curve(1) = {1}; Physical Curve(2) = {2, 5};\n"
      << "Physical Curve(3) = {6}; Physical Curve(4) = {4, 7};\n"
      << "Physical Curve(5) = {3};\n";
  }


  std::string
  material(const unsigned int id, const double k0)
  {
    return "subsection Material " + std::to_string(id) +
           "\n  set Young's modulus = 1e4\n  set Poisson's ratio = 0.3\n"
           "  set Unit weight = 20\n  set K0 = " +
           std::to_string(k0) + "\nend\n";
  }


  std::string
  scene(const double k0_below, const double k0_above, const double phi)
  {
    return "subsection Mesh\n  set File = block.geo\nend\n" +
           material(1, k0_below) + material(2, k0_above) +
           "subsection Interface 5\n  set Normal stiffness = 1e8\n"
           "  set Shear stiffness = 1e8\n  set Slip criterion = mohr-coulomb\n"
           "  set Adhesion = 0\n  set Friction angle = " +
           std::to_string(phi) +
           "\nend\n"
           "subsection Initial state\n  set Procedure = K0 procedure\nend\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Constrained components = x\nend\n"
           "subsection Boundary 3\n  set Pressure = " +
           std::to_string(p) +
           "\nend\n"
           "subsection Boundary 4\n  set Constrained components = x\nend\n"
           "subsection Loading\n  set Load increments = 1\nend\n" +
           run_results::reaction_monitors_and_output();
  }


} // namespace


int
main()
{
  using truths::expect;

  write_mesh(0.3, 0.7);
  std::string failure = run_results::run_text(scene(0.6, 0.6, 30));
  double      imbalance =
    run_results::summary_number("results", "initial_out_of_balance");
  std::printf("inclined interface, K0 = 0.6 on both sides: out of balance "
              "%s 1e-10\n",
              imbalance < 1e-10 ? "below" : "ABOVE");
  expect(failure.empty(), "the run succeeds" + failure);
  expect(imbalance < 1e-10, "the tractions balance the stresses beside them");

  failure = run_results::run_text(scene(0.5, 0.6, 30));
  std::printf("inclined interface, K0 = 0.5 below and 0.6 above: %s\n",
              failure.c_str());
  expect(failure.find("entry 'Material ") != std::string::npos &&
           failure.find("/K0'") != std::string::npos &&
           failure.find("different tractions") != std::string::npos,
         "refused, naming a side's Material <id>/K0");

  failure = run_results::run_text(scene(0.6, 0.6, 2));
  std::printf("inclined interface, phi = 2: %s\n", failure.c_str());
  expect(failure.find("Interface 5/Friction angle") != std::string::npos &&
           failure.find("outside its slip surface") != std::string::npos,
         "refused, naming Interface 5/Friction angle");

  write_mesh(0.5, 0.5);
  failure   = run_results::run_text(scene(0.5, 0.7, 30));
  imbalance = run_results::summary_number("results", "initial_out_of_balance");
  std::printf("horizontal interface, K0 = 0.5 below and 0.7 above: out of "
              "balance %s 1e-10\n",
              imbalance < 1e-10 ? "below" : "ABOVE");
  expect(failure.empty(), "the run succeeds" + failure);
  expect(imbalance < 1e-10, "the tractions balance the stresses beside them");
  double     worst = 0;
  const auto rows  = run_results::read_csv("results/interface-5-0001.csv");
  expect(rows.size() > 8, "the interface's profile has its points");
  for (const auto &row : rows)
    {
      const double exact = -(gamma_w * (1 - row.at("y")) + p);
      worst              = std::max({worst,
                                     std::abs(row.at("normal_traction") / exact - 1),
                                     std::abs(row.at("shear_traction"))});
    }
  std::printf("after the pressure p: sigma_n = -(gamma (H - y) + p), no "
              "shear, %s 1e-8\n",
              worst < 1e-8 ? "within" : "NOT within");
  expect(worst < 1e-8, "the oedometric traction on the interface");
  return truths::conclude();
}
