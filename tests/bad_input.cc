// Truth checked: bad input is refused with one clear message that names the
// file, the entry (or id) and what was expected; the exit status is
// non-zero; and nothing is written: the output directory does not exist
// afterwards. The whole program runs in-process through
// run_command_line(), on files this test writes into its own directory.
#include <thinlayer/command_line.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  // A valid scene: two materials (1, 2), boundaries 1 (bottom) and 2 (top).
  const std::string good_geo = R"(
DefineConstant[ height = {1, Name "Parameters/height"} ];
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, height, 0};
Point(4) = {0, height, 0}; Point(5) = {0, 2*height, 0}; Point(6) = {1, 2*height, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {3, 6}; Line(6) = {6, 5}; Line(7) = {5, 4};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Transfinite Curve{:} = 3; Transfinite Surface{1, 2}; Recombine Surface{1, 2};
Physical Surface("lower", 1) = {1}; Physical Surface("upper", 2) = {2};
Physical Curve("bottom", 1) = {1}; Physical Curve("top", 2) = {6};
)";

  std::string
  scene(const std::string &mesh      = "good.geo",
        const std::string &material1 = "",
        const std::string &extra     = "")
  {
    return "subsection Mesh\n  set File = " + mesh +
           "\nend\n"
           "subsection Material 1\n" +
           material1 +
           "end\n"
           "subsection Material 2\nend\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Traction = 0; -1\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
           "subsection Output\n  set Directory = results\n  set Print "
           "timing = false\nend\n" +
           extra;
  }

  void
  check(const std::string &what, const std::vector<std::string> &arguments)
  {
    std::filesystem::remove_all("results");
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line(arguments, out, err);
    std::cout << "* " << what << "\n  exit status " << status
              << ", results written: "
              << (std::filesystem::exists("results") ? "yes" : "no") << "\n  "
              << err.str() << '\n';
  }
} // namespace

int
main()
{
  write("good.geo", good_geo);
  write("triangles.geo",
        "Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n"
        "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
        "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"
        "Physical Surface(1) = {1}; Physical Curve(1) = {1};\n"
        "Physical Curve(2) = {2};\n");
  write("broken.geo", "Point(1) = {0, 0;\n");

  // The valid scene runs, so that every failure below is due to its one
  // change.
  write("good.prm", scene());
  {
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line({"good.prm"}, out, err);
    std::cout << "* the valid scene: exit status " << status
              << ", summary written: "
              << (std::filesystem::exists("results/summary.json") ? "yes"
                                                                  : "no")
              << "\n\n";
  }

  check("a parameter file that does not exist", {"missing.prm"});

  write("unknown-entry.prm", scene("good.geo", "  set Youngs modulus = 10\n"));
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

  write("element.prm",
        scene("good.geo",
              "",
              "subsection Discretisation\n  set Element = Q4\nend\n"));
  check("an element that does not exist", {"element.prm"});

  write("increments.prm",
        scene("good.geo",
              "",
              "subsection Loading\n  set Load increments = 0.5, 3*\nend\n"));
  check("malformed load increments", {"increments.prm"});

  write("expression.prm",
        scene("good.geo",
              "",
              "subsection Boundary 2\n  set Traction = 0; -(1 + \nend\n"));
  check("a traction expression that does not parse", {"expression.prm"});

  write("no-mesh.prm", scene("nowhere.geo"));
  check("a mesh file that does not exist", {"no-mesh.prm"});

  write("broken.prm", scene("broken.geo"));
  check("a .geo that gmsh rejects", {"broken.prm"});

  write("triangles.prm", scene("triangles.geo"));
  check("a mesh of triangles", {"triangles.prm"});

  write("geometry.prm",
        scene("good.geo",
              "",
              "subsection Mesh\n  set Geometry parameters = heigth=2\nend\n"));
  check("a geometry parameter the .geo does not have", {"geometry.prm"});

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

  write("monitor.prm",
        scene("good.geo",
              "",
              "subsection Monitors\n  set Displacement boundary id = 9\n"
              "end\n"));
  check("a monitor on a boundary id the mesh does not have", {"monitor.prm"});

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

  write("cohesion.prm", scene("good.geo", "  set Yield criterion = tresca\n"));
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
  check("a Fourier mesh on the axis without an axis boundary id", {"axis.prm"});

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
  check("the body-load criterion with Newton",
        {"good.prm",
         "-s",
         "Solver/Method=newton",
         "-s",
         "Solver/Convergence criterion=body loads"});
  check("the body-load criterion with the default method (Newton fallback)",
        {"good.prm", "-s", "Solver/Convergence criterion=body loads"});
}
