// The shared part of the bad_input tests: a valid scene whose results
// every check starts from, and check(), which runs the program in-process
// on a bad variant and prints its exit status, whether the previous run
// survived byte for byte, whether a staging directory was left, and the
// message.
#ifndef thinlayer_tests_bad_input_utilities_h
#define thinlayer_tests_bad_input_utilities_h

#include <thinlayer/app/command_line.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace bad_input
{
  inline void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  // A valid scene: two materials (1, 2), boundaries 1 (bottom) and 2 (top).
  inline std::string
  read_text(const std::string &name)
  {
    std::ostringstream text;
    text << std::ifstream(name).rdbuf();
    return text.str();
  }

  /// The value of "key" in DIRECTORY/summary.json, as written.
  inline std::string
  summary_entry(const std::string &directory, const std::string &key)
  {
    const std::string text = read_text(directory + "/summary.json");
    const auto        at   = text.find("\"" + key + "\": ");
    if (at == std::string::npos)
      return "(none)";
    const auto begin = at + key.size() + 4;
    return text.substr(begin, text.find_first_of(",\n", begin) - begin);
  }

  inline const std::string good_geo = R"(
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

  inline std::string
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

  /**
   * A gmsh 2.2 mesh of quadrilaterals on @p nodes ("x y" each), material
   * id 1; boundary id 1 along nodes 1-2 and 2 along the last two nodes of
   * the last quad.
   */
  inline void
  write_msh(const std::string                   &name,
            const std::vector<std::string>      &nodes,
            const std::vector<std::vector<int>> &quads)
  {
    std::ostringstream msh;
    msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
        << nodes.size() << '\n';
    for (unsigned int i = 0; i < nodes.size(); ++i)
      msh << i + 1 << ' ' << nodes[i] << " 0\n";
    const auto &last = quads.back();
    msh << "$EndNodes\n$Elements\n"
        << quads.size() + 2 << "\n1 1 2 1 1 1 2\n2 1 2 2 2 " << last[2] << ' '
        << last[3] << '\n';
    for (unsigned int k = 0; k < quads.size(); ++k)
      msh << k + 3 << " 3 2 1 1 " << quads[k][0] << ' ' << quads[k][1] << ' '
          << quads[k][2] << ' ' << quads[k][3] << '\n';
    msh << "$EndElements\n";
    write(name, msh.str());
  }

  /// A scene on @p mesh with one material (1) and boundaries 1 and 2.
  inline std::string
  one_material_scene(const std::string &mesh)
  {
    return "subsection Mesh\n  set File = " + mesh +
           "\nend\nsubsection Material 1\nend\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Traction = 0; -1\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
           "subsection Output\n  set Directory = results\n  set Print "
           "timing = false\nend\n";
  }

  /// Every file under @p directory with its contents.
  inline std::map<std::string, std::string>
  contents(const std::string &directory)
  {
    std::map<std::string, std::string> files;
    if (std::filesystem::exists(directory))
      for (const auto &entry :
           std::filesystem::recursive_directory_iterator(directory))
        {
          std::ostringstream text;
          if (entry.is_regular_file())
            text << std::ifstream(entry.path()).rdbuf();
          files[entry.path().lexically_relative(directory).string()] =
            text.str();
        }
    return files;
  }

  /// Whether a run's staging directory (".results.partial-...") is left.
  inline bool
  staging_left()
  {
    for (const auto &entry : std::filesystem::directory_iterator("."))
      if (entry.path().filename().string().rfind(".results.", 0) == 0)
        return true;
    return false;
  }

  /// The results of the valid scene, which every check starts from.
  inline std::map<std::string, std::string> previous_run;

  inline void
  check(const std::string &what, const std::vector<std::string> &arguments)
  {
    std::filesystem::remove_all("results");
    std::filesystem::copy("previous",
                          "results",
                          std::filesystem::copy_options::recursive);
    std::ostringstream out, err;
    const int status = thinlayer::run_command_line(arguments, out, err);
    // The project's own files by their place in it, whatever the clone's.
    std::string       message = err.str();
    const std::string top     = std::string(SOURCE_DIR) + "/../../";
    for (std::size_t at = message.find(top); at != std::string::npos;
         at             = message.find(top))
      message.replace(at, top.size(), "");
    std::cout << "* " << what << "\n  exit status " << status
              << ", previous run kept: "
              << (contents("results") == previous_run ? "yes" : "NO")
              << ", foreign file kept: "
              << (read_text("thesis.tex") == "\\chapter{}\n" ? "yes" : "NO")
              << ", staging left behind: " << (staging_left() ? "YES" : "no")
              << "\n  " << message << '\n';
  }
  /// Print the valid scene's exit status @p status and keep its results
  /// as the run every check starts from ("previous").
  inline void
  keep_valid_run(const int status)
  {
    std::cout << "* the valid scene: exit status " << status
              << ", summary written: "
              << (std::filesystem::exists("results/summary.json") ? "yes"
                                                                  : "no")
              << "\n\n";
    std::filesystem::remove_all("previous");
    std::filesystem::rename("results", "previous");
    previous_run = contents("previous");
  }

  /// A scene on the interface patch (@p meshes/interface-patch.geo) whose
  /// interface curve 3 is far too soft for the cells beside it.
  inline std::string
  soft_interface_scene(const std::string &meshes)
  {
    return "subsection Mesh\n  set File = " + meshes +
           "interface-patch.geo\nend\n"
           "subsection Material 1\nend\n"
           "subsection Interface 3\n  set Shear stiffness = 1e-20\n"
           "end\n"
           "subsection Boundary 1\n  set Constrained components = x, y\nend\n"
           "subsection Boundary 2\n  set Traction = 1; -1\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\nend\n"
           "subsection Output\n  set Directory = results\nend\n";
  }

  /// The files every check uses, and the valid scene, whose results every check
  /// starts from.
  inline void
  write_valid_scene()
  {
    write("good.geo", good_geo);
    // A file of the user's beside the results, which no check may touch.
    write("thesis.tex", "\\chapter{}\n");
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
      keep_valid_run(thinlayer::run_command_line({"good.prm"}, out, err));
    }
  }
} // namespace bad_input

#endif
