// Truth checked: bad input of 3D scenes (Kinematics/Type = 3d) is refused
// as in 2D, with one clear message naming the file, the entry (or the
// mesh) and what was expected, a non-zero exit, and nothing written (the
// previous run kept byte for byte): the elements and components of the
// other dimension, entries that take one coordinate or expression per
// component, interface elements on a surface the mesh does not have, and
// hexahedra that are inverted, folded, flat or tiny.
#include "../common/bad_input_utilities.h"

using namespace bad_input;

namespace
{
  /// A gmsh 2.2 mesh of hexahedra on @p nodes ("x y z" each), material id
  /// 1, gmsh's node order; boundary id 1 on the first hexahedron's face
  /// 1-2-3-4 and 2 on the last one's face 5-6-7-8.
  void
  write_hex_msh(const std::string                   &name,
                const std::vector<std::string>      &nodes,
                const std::vector<std::vector<int>> &hexes)
  {
    std::ostringstream msh;
    msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
        << nodes.size() << '\n';
    for (unsigned int i = 0; i < nodes.size(); ++i)
      msh << i + 1 << ' ' << nodes[i] << '\n';
    const auto &first = hexes.front();
    const auto &last  = hexes.back();
    msh << "$EndNodes\n$Elements\n"
        << hexes.size() + 2 << "\n1 3 2 1 1 " << first[0] << ' ' << first[1]
        << ' ' << first[2] << ' ' << first[3] << "\n2 3 2 2 2 " << last[4]
        << ' ' << last[5] << ' ' << last[6] << ' ' << last[7] << '\n';
    for (unsigned int k = 0; k < hexes.size(); ++k)
      {
        msh << k + 3 << " 5 2 1 1";
        for (const int n : hexes[k])
          msh << ' ' << n;
        msh << '\n';
      }
    msh << "$EndElements\n";
    write(name, msh.str());
  }

  /// A 3D scene on @p mesh: material 1 (@p material lines in its
  /// section), the base (1) held, the traction @p traction on the top (2),
  /// @p monitors lines in the Monitors section, 3x3x3 Gauss points, and
  /// @p extra appended.
  std::string
  solid_scene(const std::string &mesh,
              const std::string &extra    = "",
              const std::string &traction = "0; -1; 0",
              const std::string &monitors = "",
              const std::string &gauss    = "3")
  {
    return "subsection Mesh\n  set File = " + mesh +
           "\nend\nsubsection Kinematics\n  set Type = 3d\nend\n"
           "subsection Discretisation\n  set Gauss points per direction = " +
           gauss +
           "\nend\n"
           "subsection Material 1\nend\n"
           "subsection Boundary 1\n  set Constrained components = x, y, "
           "z\nend\n"
           "subsection Boundary 2\n  set Traction = " +
           traction +
           "\nend\n"
           "subsection Monitors\n  set Displacement boundary id = 2\n" +
           monitors +
           "end\n"
           "subsection Output\n  set Directory = results\n  set Print "
           "timing = false\nend\n" +
           extra;
  }


  /// The unit cube's corners in gmsh's order, the top four moved by
  /// @p top (four "x y z").
  std::vector<std::string>
  cube(
    const std::vector<std::string> &top = {"0 0 1", "1 0 1", "1 1 1", "0 1 1"})
  {
    std::vector<std::string> nodes = {"0 0 0", "1 0 0", "1 1 0", "0 1 0"};
    nodes.insert(nodes.end(), top.begin(), top.end());
    return nodes;
  }


  /// Entries of the wrong dimension.
  void
  check_entries()
  {
    write("q20-2d.prm",
          scene("good.geo",
                "",
                "subsection Discretisation\n  set Element = Q20\nend\n"));
    check("a 20-node hexahedron on a 2D mesh", {"q20-2d.prm"});

    write("q8-3d.prm", solid_scene("cube.msh"));
    check("Q8 written out in 3d",
          {"q8-3d.prm", "-s", "Discretisation/Element=Q8"});

    write("reduced-3d.prm", solid_scene("cube.msh", "", "0; -1; 0", "", "2"));
    check("one hexahedron with 2x2x2 points (singular)", {"reduced-3d.prm"});

    write("z-2d.prm",
          "subsection Mesh\n  set File = good.geo\nend\n"
          "subsection Material 1\nend\nsubsection Material 2\nend\n"
          "subsection Boundary 1\n  set Constrained components = x, z\nend\n"
          "subsection Boundary 2\n  set Traction = 0; -1\nend\n"
          "subsection Monitors\n  set Displacement boundary id = 2\nend\n");
    check("the component z in plane strain", {"z-2d.prm"});

    write("load-z-2d.prm", scene());
    check("a reaction along z in plane strain",
          {"load-z-2d.prm",
           "-s",
           "Monitors/Load measure=reaction",
           "-s",
           "Monitors/Load boundary id=1",
           "-s",
           "Monitors/Load component=z"});

    write("traction-3d.prm", solid_scene("cube.msh", "", "0; -1"));
    check("two traction expressions in 3d", {"traction-3d.prm"});

    write("point-3d.prm",
          solid_scene("cube.msh",
                      "",
                      "0; -1; 0",
                      "  set Displacement measure = point\n"
                      "  set Displacement point = 0.5, 0.5\n"));
    check("a monitored point with two coordinates in 3d", {"point-3d.prm"});

    write("interface-3d.prm",
          solid_scene("cube.msh", "subsection Interface 3\nend\n"));
    check("interface elements on a surface the mesh does not have",
          {"interface-3d.prm"});

    // Two cubes stacked along z, their base (z = 0) and top held in their
    // plane (x, y) only: free to move along z, and nothing else.
    write_hex_msh("two-cubes.msh",
                  {"0 0 0",
                   "1 0 0",
                   "1 1 0",
                   "0 1 0",
                   "0 0 1",
                   "1 0 1",
                   "1 1 1",
                   "0 1 1",
                   "0 0 2",
                   "1 0 2",
                   "1 1 2",
                   "0 1 2"},
                  {{1, 2, 3, 4, 5, 6, 7, 8}, {5, 6, 7, 8, 9, 10, 11, 12}});
    write("sliding.prm", solid_scene("two-cubes.msh", "", "0"));
    check("a 3D body held in x and y only, on its base and top (free along z)",
          {"sliding.prm",
           "-s",
           "Boundary 1/Constrained components=x, y",
           "-s",
           "Boundary 2/Constrained components=x, y",
           "-s",
           "Boundary 2/Displacement=0.001; 0; 0"});

    write("good-2d-mesh-3d.prm", solid_scene("good.geo"));
    check("a 2D geometry under 3d kinematics", {"good-2d-mesh-3d.prm"});
  }


  /// Hexahedra that are not usable cells.
  void
  check_cells()
  {
    write_hex_msh("twisted.msh",
                  cube({"0 0 1", "1 0 1", "0 1 1", "1 1 1"}),
                  {{1, 2, 3, 4, 5, 6, 7, 8}});
    write("twisted.prm", solid_scene("twisted.msh"));
    check("a hexahedron whose top face is folded", {"twisted.prm"});

    write_hex_msh("flat.msh",
                  cube({"0 0 0", "1 0 0", "1 1 0", "0 1 0"}),
                  {{1, 2, 3, 4, 5, 6, 7, 8}});
    write("flat.prm", solid_scene("flat.msh"));
    check("a hexahedron of zero volume", {"flat.prm"});

    write_hex_msh("sliver.msh",
                  cube({"0 0 1e-19", "1 0 1e-19", "1 1 1e-19", "0 1 1e-19"}),
                  {{1, 2, 3, 4, 5, 6, 7, 8}});
    write("sliver.prm", solid_scene("sliver.msh"));
    check("a hexahedron 1e-19 thick", {"sliver.prm"});

    write_hex_msh("repeated.msh", cube(), {{1, 2, 3, 3, 5, 6, 7, 8}});
    write("repeated.prm", solid_scene("repeated.msh"));
    check("a hexahedron with a repeated corner", {"repeated.prm"});
  }
} // namespace


int
main()
{
  write_valid_scene();
  // The valid 3D scene, one cube, runs and replaces the previous run.
  write_hex_msh("cube.msh", cube(), {{1, 2, 3, 4, 5, 6, 7, 8}});
  write("cube.prm", solid_scene("cube.msh"));
  check("(the valid one-cube scene: it runs, and replaces the previous run)",
        {"cube.prm"});
  check_entries();
  check_cells();
}
