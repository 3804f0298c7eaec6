// Truth checked: bad input is refused with one clear message that names the
// file, the entry (or id) and what was expected; the exit status is
// non-zero; and nothing is written: the output directory still holds the
// previous run, file for file and byte for byte (each check starts from a
// copy of a valid run's results). The whole program runs in-process
// through run_command_line(), on files this test writes into its own
// directory. bad_output holds the cases of the output path (the results
// directory, signals, a full disk).
#include "../common/bad_input_utilities.h"

using namespace bad_input;

namespace
{
  /// Files, entries and values that cannot be read.
  void
  check_files_and_entries()
  {
    check("a parameter file that does not exist", {"missing.prm"});

    write("unknown-entry.prm",
          scene("good.geo", "  set Youngs modulus = 10\n"));
    check("an unknown entry", {"unknown-entry.prm"});

    write("unknown-section.prm",
          scene("good.geo", "", "subsection Solvers\nend\n"));
    check("an unknown subsection", {"unknown-section.prm"});

    write("malformed.prm",
          scene("good.geo", "  set Young's modulus = ten thousand\n"));
    check("a malformed value", {"malformed.prm"});

    write("poisson.prm", scene("good.geo", "  set Poisson's ratio = 0.5\n"));
    check("Poisson's ratio of 0.5", {"poisson.prm"});

    write("young.prm", scene("good.geo", "  set Young's modulus = 0\n"));
    check("Young's modulus of 0", {"young.prm"});

    write("weight.prm", scene("good.geo", "  set Unit weight = -18\n"));
    check("a negative unit weight", {"weight.prm"});

    write("element.prm",
          scene("good.geo",
                "",
                "subsection Discretisation\n  set Element = Q4\nend\n"));
    check("an element that does not exist", {"element.prm"});

    // One row of cells under Fourier kinematics, held only axially: Q8
    // solves it (tests/scenes/fourier_cylinder_plastic.prm), Q9 with 2x2 points
    // is singular.
    write("q9-reduced.prm",
          "subsection Mesh\n  set File = " + std::string(SOURCE_DIR) +
            "/../../meshes/block.geo\n  set Geometry parameters = x0=1, "
            "height=0.25, nx=8, ny=1\nend\n"
            "subsection Kinematics\n  set Type = fourier\n  set Harmonics "
            "= 0\nend\n"
            "subsection Discretisation\n  set Element = Q9\nend\n"
            "subsection Material 1\nend\n"
            "subsection Boundary 1\n  set Constrained components = z\nend\n"
            "subsection Boundary 3\n  set Constrained components = z\nend\n"
            "subsection Boundary 4\n  set Pressure = 1\nend\n"
            "subsection Monitors\n  set Displacement boundary id = 4\nend\n"
            "subsection Output\n  set Directory = results\nend\n");
    check("Q9 with 2x2 points on a mesh too coarse to suppress its "
          "zero-energy modes",
          {"q9-reduced.prm"});

    write("interface-id.prm",
          scene("good.geo",
                "",
                "subsection Layers\n  set Material ids = 7\nend\n"));
    check("an interface with no Material section", {"interface-id.prm"});

    write("interface-thick.prm",
          scene("good.geo",
                "",
                "subsection Layers\n  set Material ids = 1\nend\n"));
    check("an interface more than one cell thick", {"interface-thick.prm"});

    // Two blocks joined by zero-thickness elements 1e7 times as stiff as
    // the cells beside them (E / h = 1e5 / 0.25).
    write("interface-stiffness.prm",
          "subsection Mesh\n  set File = " + std::string(SOURCE_DIR) +
            "/../../meshes/interface-patch.geo\nend\n"
            "subsection Material 1\nend\n"
            "subsection Interface 3\n  set Normal stiffness = 4e12\n"
            "end\n"
            "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
            "subsection Boundary 2\n  set Traction = 0; -1\nend\n"
            "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
            "subsection Output\n  set Directory = results\nend\n");
    check("zero-thickness elements too stiff for round-off",
          {"interface-stiffness.prm"});

    write("increments.prm",
          scene("good.geo",
                "",
                "subsection Loading\n  set Load increments = 0.5, 3*\nend\n"));
    check("malformed load increments", {"increments.prm"});

    check("a traction expression that does not parse",
          {"good.prm", "-s", "Boundary 2/Traction=0; -(1 + "});
  }


  /// Meshes, and ids that do not match between the mesh and the file.
  void
  check_meshes_and_ids()
  {
    write("no-mesh.prm", scene("nowhere.geo"));
    check("a mesh file that does not exist", {"no-mesh.prm"});

    write("broken.prm", scene("broken.geo"));
    check("a .geo that gmsh rejects", {"broken.prm"});

    write("triangles.prm", scene("triangles.geo"));
    check("a mesh of triangles", {"triangles.prm"});

    check("a geometry parameter the .geo does not have",
          {"good.prm", "-s", "Mesh/Geometry parameters=heigth=2"});

    write("missing-material.prm",
          "subsection Mesh\n  set File = good.geo\nend\n"
          "subsection Material 1\nend\n"
          "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
          "subsection Monitors\n  set Displacement boundary id = 1\nend\n"
          "subsection Output\n  set Directory = results\nend\n");
    check("a physical surface of the mesh without a material",
          {"missing-material.prm"});

    write("extra-material.prm",
          scene("good.geo", "", "subsection Material 5\nend\n"));
    check("a material id the mesh does not have", {"extra-material.prm"});

    write("extra-boundary.prm",
          scene("good.geo",
                "",
                "subsection Boundary 7\n  set Constrained components = x\n"
                "end\n"));
    check("a boundary id the mesh does not have", {"extra-boundary.prm"});

    check("a monitor on a boundary id the mesh does not have",
          {"good.prm", "-s", "Monitors/Displacement boundary id=9"});

    write("unrestrained.prm",
          "subsection Mesh\n  set File = good.geo\nend\n"
          "subsection Material 1\nend\nsubsection Material 2\nend\n"
          "subsection Boundary 2\n  set Traction = 0; -1\nend\n"
          "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
          "subsection Output\n  set Directory = results\nend\n");
    check("a body with no support", {"unrestrained.prm"});

    write("sweep.prm",
          scene("good.geo",
                "",
                "subsection Sweep\n  set Values = height = 1, tall\nend\n"));
    check("a sweep of a geometry parameter over a non-number", {"sweep.prm"});

    write("sweep-entry.prm",
          scene("good.geo",
                "",
                "subsection Sweep\n  set Values = Material 1/Poisson's ratio "
                "= 0.2, 0.5\nend\n"));
    check("a sweep with one invalid run", {"sweep-entry.prm"});
  }


  /// Materials, Fourier axes, overrides and solver settings that do not fit.
  void
  check_materials_and_solver()
  {
    write("cohesion.prm",
          scene("good.geo", "  set Yield criterion = tresca\n"));
    check("a Tresca material without cohesion", {"cohesion.prm"});

    write("dilation.prm",
          scene("good.geo",
                "  set Yield criterion = mohr-coulomb\n  set Friction angle = "
                "20\n  set Dilation angle = 25\n"));
    check("a dilation angle above the friction angle", {"dilation.prm"});

    write("axis.prm",
          "subsection Mesh\n  set File = good.geo\nend\n"
          "subsection Kinematics\n  set Type = fourier\nend\n"
          "subsection Material 1\nend\nsubsection Material 2\nend\n"
          "subsection Boundary 1\n  set Constrained components = r, z, theta\n"
          "end\n"
          "subsection Boundary 2\n  set Traction = 1; 0; 0\nend\n"
          "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
          "subsection Output\n  set Directory = results\nend\n");
    check("a Fourier mesh on the axis without an axis boundary id",
          {"axis.prm"});

    check("an override of an entry that does not exist",
          {"good.prm", "-s", "Material 1/Stiffness=3"});
    check("an override with a value out of its pattern",
          {"good.prm", "-s", "Discretisation/Gauss points per direction=7"});
    check("an override that is not Section/Entry=value",
          {"good.prm", "-s", "Material 1/Young's modulus"});
    check("an unknown option", {"good.prm", "--fast"});
    check("the residual criterion with the viscoplastic method",
          {"good.prm",
           "-s",
           "Solver/Method=viscoplastic",
           "-s",
           "Solver/Convergence criterion=residual"});
    check("a revolved 3D view in plane strain",
          {"good.prm", "-s", "Output/3D view slices=12"});
    check("a torque in plane strain",
          {"good.prm",
           "-s",
           "Monitors/Load measure=reaction",
           "-s",
           "Monitors/Load boundary id=1",
           "-s",
           "Monitors/Load component=torque"});
    check("the body-load criterion with Newton",
          {"good.prm",
           "-s",
           "Solver/Method=newton",
           "-s",
           "Solver/Convergence criterion=body loads"});
    check("the body-load criterion with the default method (Newton fallback)",
          {"good.prm", "-s", "Solver/Convergence criterion=body loads"});
    check("single precision with Newton",
          {"good.prm",
           "-s",
           "Solver/Method=newton",
           "-s",
           "Solver/Single precision=true"});
  }


  /// Values that are not finite numbers, or would make some.
  void
  check_values()
  {
    check("a Young's modulus that overflows the stiffness",
          {"good.prm", "-s", "Material 1/Young's modulus=1e308"});
    check("a traction that is infinite",
          {"good.prm", "-s", "Boundary 2/Traction=0; -1e-3/0"});
    check("a traction that is not a number",
          {"good.prm", "-s", "Boundary 2/Traction=0; sqrt(-1)"});
    check("a traction that is not a number on part of the boundary",
          {"good.prm", "-s", "Boundary 2/Traction=0; log(x-0.5)"});
    check("a pressure that is infinite",
          {"good.prm",
           "-s",
           "Boundary 2/Traction=0",
           "-s",
           "Boundary 2/Pressure=1/0"});
    check("a prescribed displacement that is not a number",
          {"good.prm", "-s", "Boundary 1/Displacement=0; sqrt(-1)"});
    check("a load increment that is not finite",
          {"good.prm", "-s", "Loading/Load increments=0.5, 1e999"});
  }


  /// Entries that would be ignored or would make the run meaningless.
  void
  check_ignored_entries()
  {
    check("a directory given as the parameter file", {"."});
    check("a tolerance of 1", {"good.prm", "-s", "Solver/Tolerance=1"});
    check("a tolerance above 1", {"good.prm", "-s", "Solver/Tolerance=5"});
    check("a friction angle on a Tresca material",
          {"good.prm",
           "-s",
           "Material 1/Yield criterion=tresca",
           "-s",
           "Material 1/Cohesion=1",
           "-s",
           "Material 1/Friction angle=30"});
    check("a dilation angle on a von Mises material",
          {"good.prm",
           "-s",
           "Material 1/Yield criterion=von mises",
           "-s",
           "Material 1/Cohesion=1",
           "-s",
           "Material 1/Dilation angle=5"});
    check("a cohesion on an elastic material",
          {"good.prm", "-s", "Material 1/Cohesion=1"});
    check("a traction on a constrained component",
          {"good.prm", "-s", "Boundary 1/Traction=0; -1"});
    check("a pressure on a boundary constrained in every component",
          {"good.prm", "-s", "Boundary 1/Pressure=1"});
    check("a repeat count that is not a whole number",
          {"good.prm", "-s", "Loading/Load increments=1e9*0.1"});
    check("more load steps than memory holds",
          {"good.prm", "-s", "Loading/Load increments=1000000000*0.1"});
    write("twice-section.prm",
          scene() + "subsection Material 1\n  set Young's modulus = 5\nend\n");
    check("the same subsection twice", {"twice-section.prm"});
    write("twice-entry.prm",
          scene() +
            "subsection Solver\n  set Tolerance = 1e-3\n  set Tolerance "
            "= 1e-4\nend\n");
    check("the same entry twice in one subsection", {"twice-entry.prm"});
    std::string point = scene();
    point.replace(point.find("set Displacement boundary id = 2"),
                  32,
                  "set Displacement measure = point\n  set Displacement "
                  "point = 5, 5");
    write("point.prm", point);
    check("a monitor point outside the mesh", {"point.prm"});

    check("a mesh with more cells than Mesh/Maximum cells",
          {"good.prm", "-s", "Mesh/Maximum cells=3"});
  }


  /// Fourier stations that cannot project the harmonics exactly.
  void
  check_fourier_stations()
  {
    // axis.prm (a Fourier scene, check_materials_and_solver()) fails on
    // its stations before its axis.
    check("Fourier stations too few for the highest harmonic",
          {"axis.prm",
           "-s",
           "Kinematics/Harmonics=1, 3",
           "-s",
           "Kinematics/Stations=0, 90, 180"});
    check("a Fourier reaction from a harmonic the series does not have",
          {"axis.prm",
           "-s",
           "Monitors/Load measure=reaction",
           "-s",
           "Monitors/Load boundary id=1",
           "-s",
           "Monitors/Load component=torque"});
    check("one Fourier station for harmonics other than 0",
          {"axis.prm", "-s", "Kinematics/Stations=0"});
    check("Fourier stations not equally spaced",
          {"axis.prm",
           "-s",
           "Kinematics/Harmonics=1, 3",
           "-s",
           "Kinematics/Stations=0, 10, 45, 90, 135, 180"});
  }


  /// Cells that are not convex quadrilaterals of a usable size.
  void
  check_cells()
  {
    write_msh("square.msh", {"0 0", "1 0", "1 1", "0 1"}, {{1, 2, 3, 4}});
    write("square.prm", one_material_scene("square.msh"));
    check("(the valid one-cell mesh: it runs, and replaces the previous run)",
          {"square.prm"});
    write_msh("repeated.msh", {"0 0", "1 0", "1 1", "0 1"}, {{1, 2, 3, 3}});
    write("repeated.prm", one_material_scene("repeated.msh"));
    check("a quadrilateral with a repeated vertex", {"repeated.prm"});
    write_msh("collapsed.msh", {"0 0", "1 0", "1 1", "1 1"}, {{1, 2, 3, 4}});
    write("collapsed.prm", one_material_scene("collapsed.msh"));
    check("a quadrilateral collapsed to a triangle", {"collapsed.prm"});
    write_msh("bowtie.msh", {"0 0", "1 0", "0 1", "1 1"}, {{1, 2, 3, 4}});
    write("bowtie.prm", one_material_scene("bowtie.msh"));
    check("a bow-tie quadrilateral", {"bowtie.prm"});
    write_msh("reentrant.msh",
              {"0 0", "1 0", "0.3 0.3", "0 1"},
              {{1, 2, 3, 4}});
    write("reentrant.prm", one_material_scene("reentrant.msh"));
    check("a quadrilateral that is not convex", {"reentrant.prm"});
    write_msh("flat.msh", {"0 0", "1 0", "2 0", "3 0"}, {{1, 2, 3, 4}});
    write("flat.prm", one_material_scene("flat.msh"));
    check("a quadrilateral of zero area", {"flat.prm"});
    write_msh(
      "sliver.msh",
      {"0 0", "1 0", "1 1", "0 1", "1 1.0000000000001", "0 1.0000000000001"},
      {{1, 2, 3, 4}, {4, 3, 5, 6}});
    write("sliver.prm", one_material_scene("sliver.msh"));
    check("a cell 1e-13 thick in a mesh of size 1", {"sliver.prm"});
  }


  /// Meshes deal.II reads that are not the body they describe, and mesh
  /// files that are not what they say: refused, naming the node, the
  /// element or the group.
  void
  check_mesh_files()
  {
    const std::vector<std::string> square = {"0 0", "1 0", "1 1", "0 1"};
    for (const auto &[what, bad] :
         std::vector<std::pair<std::string, std::string>>{
           {"a coordinate that is no number ('abc')", "abc 1"},
           {"a coordinate 'nan'", "nan 1"},
           {"a coordinate with trailing characters ('1junk')", "1junk 1"}})
      {
        std::vector<std::string> nodes = square;
        nodes[2]                       = bad;
        write_msh("coordinate.msh", nodes, {{1, 2, 3, 4}});
        write("coordinate.prm", one_material_scene("coordinate.msh"));
        check("a .msh with " + what, {"coordinate.prm"});
      }

    write_msh("twice.msh", square, {{1, 2, 3, 4}});
    std::string text = read_text("twice.msh");
    text.replace(text.find("$Nodes\n4\n"), 9, "$Nodes\n5\n2 5 5 0\n");
    write("twice.msh", text);
    write("twice.prm", one_material_scene("twice.msh"));
    check("a .msh that defines node 2 twice", {"twice.prm"});

    write_msh("tag.msh", square, {{1, 2, 3, 4}});
    text = read_text("tag.msh");
    text.replace(text.find("3 2 1 1 1 2 3 4"), 15, "3 2 -2 1 1 2 3 4");
    write("tag.msh", text);
    write("tag.prm", one_material_scene("tag.msh"));
    check("a .msh whose cell has the physical tag -2", {"tag.prm"});

    // A large cell beside two small ones: node 7 at (1, 0.5) lies on the
    // large cell's side 2-3.
    write_msh("hanging.msh",
              {"0 0", "1 0", "1 1", "0 1", "2 0", "2 0.5", "1 0.5", "2 1"},
              {{1, 2, 3, 4}, {2, 5, 6, 7}, {7, 6, 8, 3}});
    write("hanging.prm", one_material_scene("hanging.msh"));
    check("a hanging node (cells joined at corners only)", {"hanging.prm"});

    // Two cells side by side, each with its own nodes along x = 1.
    write_msh("crack.msh",
              {"0 0", "1 0", "1 1", "0 1", "1 0", "2 0", "2 1", "1 1"},
              {{1, 2, 3, 4}, {5, 6, 7, 8}});
    write("crack.prm", one_material_scene("crack.msh"));
    check("duplicate points (a crack between two cells)", {"crack.prm"});

    // The second surface of the valid scene in no physical group: gmsh
    // would leave its cells out.
    std::string lost = good_geo;
    lost.replace(lost.find("Physical Surface(\"upper\", 2) = {2};"), 35, "");
    write("lost.geo", lost);
    write("lost.prm", one_material_scene("lost.geo"));
    check("a surface in no physical group", {"lost.prm"});

    // The valid scene's middle line as a physical curve of its own.
    write("inner.geo", good_geo + "Physical Curve(\"inner\", 5) = {3};\n");
    write("inner.prm", scene("inner.geo"));
    check("a physical curve inside the body, with no section for it",
          {"inner.prm"});
  }


  /// Circles the geometry draws but no surface uses curve nothing.
  void
  check_construction_circles()
  {
    // A unit square whose four corners lie on a circle of radius 1/sqrt(2)
    // drawn for construction only: its sides stay straight.
    write("circle.geo",
          "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};\n"
          "Point(4) = {0, 1, 0}; Point(5) = {0.5, 0.5, 0};\n"
          "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
          "Line(4) = {4, 1};\n"
          "Circle(5) = {1, 5, 2}; Circle(6) = {2, 5, 3};\n"
          "Circle(7) = {3, 5, 4}; Circle(8) = {4, 5, 1};\n"
          "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
          "Transfinite Curve{1, 2, 3, 4} = 2; Transfinite Surface{1};\n"
          "Recombine Surface{1};\n"
          "Physical Surface(1) = {1}; Physical Curve(1) = {1};\n"
          "Physical Curve(2) = {3};\n");
    write("circle.prm", one_material_scene("circle.geo"));
    std::ostringstream out, err;
    const int          status = thinlayer::run_command_line(
      {"circle.prm", "-s", "Output/Directory=circle"}, out, err);
    std::cout << "* (construction circles through a square's corners that no "
                 "surface uses: meshed as designed)\n  exit status "
              << status << ", a cell side curved: "
              << (out.str().find("curved") != std::string::npos ? "YES" : "no")
              << "\n\n";
  }
} // namespace


int
main()
{
  write_valid_scene();
  check_files_and_entries();
  check_meshes_and_ids();
  check_materials_and_solver();
  check_values();
  check_ignored_entries();
  check_fourier_stations();
  check_cells();
  check_mesh_files();
  check_construction_circles();
}
