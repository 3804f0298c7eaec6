// Truths checked for the one reader of gmsh meshes (MshFile), the
// triangulation built from it, and the splitting along interface curves
// and surfaces:
// 1. The triangulation is deal.II's own: for meshes/block.geo and
//    meshes/interface-patch.geo meshed by gmsh (format 2.2), for a
//    two-cell block written by hand in formats 2.2 and 4.1, and for two
//    hexahedra in 3D, every cell's vertices (in order), material id and
//    every boundary face's id equal those of GridIn::read_msh() on the same
//    text.
// 2. The 2.2 text gmsh wrote is written back byte for byte.
// 3. The block in format 4.1 gives the triangulation of format 2.2.
// 4. Splitting interface-patch.geo (nx = 4) along its curve 3: each of its
//    5 nodes gets one copy (two sectors each: the curve ends on the
//    boundary), its 4 lines become 8, the cells stay 16; in the
//    triangulation 8 faces carry id 3, in 4 coincident pairs with one cell
//    above and one below the curve. Splitting along curve 1 (the bottom, a
//    cell on one side only) is refused.
// 5. Splitting interface-patch-3d.geo (nx = 4, nz = 2) along its surface
//    3: each of its 15 nodes gets a copy, its 8 quadrilaterals become 16,
//    the hexahedra stay 32, and deal.II reads the result as our reader
//    does. A surface that ends inside the body (four hexahedra, the face
//    between two of them): only its 2 nodes on the boundary are copied, the
//    2 on its front stay joined, and both of its sides are boundary faces.
// 6. A quadrilateral naming a node twice is found (repeated_corner()), and
//    none in a good mesh.
#include <deal.II/grid/grid_in.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/gmsh_process.h>
#include <thinlayer/mesh/mesh_splitting.h>
#include <thinlayer/mesh/msh_file.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "../common/truths.h"

using namespace thinlayer;
using truths::expect;

namespace
{
  const std::string meshes = SOURCE_DIR "/../../meshes/";

  std::string
  gmsh(const std::string                   &geo,
       const std::map<std::string, double> &values,
       const unsigned int                   dimension = 2)
  {
    std::ostringstream progress; // timing-dependent lines stay out
    return run_gmsh({meshes + geo, values, 100000, "msh_file.cc", dimension},
                    progress);
  }


  /// The elements of gmsh type @p type in @p m, of physical id @p id (any
  /// where negative).
  unsigned int
  count(const MshFile &m, const int type, const long id)
  {
    unsigned int n = 0;
    for (const MshElement &e : m.elements)
      n += (e.type == type && (id < 0 || e.physical() == id));
    return n;
  }


  /// Whether @p a and @p b have the same cells (vertices in order,
  /// material ids) and boundary faces (ids), to round-off.
  template <int dim>
  bool
  same(const Triangulation<dim> &a, const Triangulation<dim> &b)
  {
    if (a.n_active_cells() != b.n_active_cells() ||
        a.n_vertices() != b.n_vertices())
      return false;
    for (auto ca = a.begin_active(), cb = b.begin_active(); ca != a.end();
         ++ca, ++cb)
      {
        if (ca->material_id() != cb->material_id())
          return false;
        for (const unsigned int v : ca->vertex_indices())
          if (ca->vertex(v).distance(cb->vertex(v)) > 1e-12)
            return false;
        for (const unsigned int f : ca->face_indices())
          if (ca->face(f)->at_boundary() != cb->face(f)->at_boundary() ||
              (ca->face(f)->at_boundary() &&
               ca->face(f)->boundary_id() != cb->face(f)->boundary_id()))
            return false;
      }
    return true;
  }


  /// Ours and deal.II's triangulation of @p text; true if the same.
  template <int dim>
  bool
  as_deal_ii_reads(const std::string &text, const std::string &name)
  {
    Triangulation<dim> ours, theirs;
    create_triangulation(MshFile(text, name), ours);
    GridIn<dim>        grid_in(theirs);
    std::istringstream in(text);
    grid_in.read_msh(in);
    const bool result = same(ours, theirs);
    std::cout << "  " << name << ": " << ours.n_active_cells() << " cells, "
              << ours.n_vertices()
              << " vertices, as deal.II reads it: " << (result ? "yes" : "NO")
              << '\n';
    return result;
  }


  // Two unit squares side by side, material 7, boundary lines 1 (bottom)
  // and 2 (top), in formats 2.2 and 4.1.
  const std::string block_2 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
6
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
$EndNodes
$Elements
6
1 1 2 1 1 1 2
2 1 2 1 1 2 3
3 1 2 2 3 4 5
4 1 2 2 3 5 6
5 3 2 7 1 1 2 5 4
6 3 2 7 1 2 3 6 5
$EndElements
)";

  const std::string block_4 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 2 1 0
1 0 0 0 2 0 0 1 1 0
3 0 1 0 2 1 0 1 2 0
1 0 0 0 2 1 0 1 7 0
$EndEntities
$Nodes
1 6 1 6
2 1 0 6
1
2
3
4
5
6
0 0 0
1 0 0
2 0 0
0 1 0
1 1 0
2 1 0
$EndNodes
$Elements
3 6 1 6
1 1 1 2
1 1 2
2 2 3
1 3 1 2
3 4 5
4 5 6
2 1 3 2
5 1 2 5 4
6 2 3 6 5
$EndElements
)";

  // Two unit cubes side by side in 3D, material 1, the face x = 0 id 4.
  const std::string hexes = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
12
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
7 0 0 1
8 1 0 1
9 2 0 1
10 0 1 1
11 1 1 1
12 2 1 1
$EndNodes
$Elements
3
1 3 2 4 1 1 4 10 7
2 5 2 1 1 1 2 5 4 7 8 11 10
3 5 2 1 1 2 3 6 5 8 9 12 11
$EndElements
)";
} // namespace


int
main()
{
  std::cout << "1. The triangulation is deal.II's\n";
  const std::string block = gmsh("block.geo", {{"nx", 5}, {"ny", 3}});
  const std::string patch = gmsh("interface-patch.geo", {});
  expect(as_deal_ii_reads<2>(block, "block.geo"), "block.geo");
  {
    // Its curve 3 runs through the body: read as it is, deal.II refuses a
    // boundary id on an interior face, and so does the reader; split, the
    // two read it alike.
    bool refused = false;
    try
      {
        Triangulation<2> tria;
        create_triangulation(MshFile(patch, "interface-patch.geo"), tria);
      }
    catch (const InputError &)
      {
        refused = true;
      }
    expect(refused, "interface-patch.geo unsplit: refused");
    expect(
      as_deal_ii_reads<2>(
        split_along_curves(MshFile(patch, "interface-patch.geo"), {3}).text(),
        "interface-patch.geo, split along curve 3"),
      "interface-patch.geo split");
  }
  expect(as_deal_ii_reads<2>(block_2, "two cells, format 2.2"), "format 2.2");
  expect(as_deal_ii_reads<2>(block_4, "two cells, format 4.1"), "format 4.1");
  expect(as_deal_ii_reads<3>(hexes, "two hexahedra"), "3D");

  std::cout << "2. Written back byte for byte\n";
  for (const std::string *text : {&block, &patch, &block_2})
    expect(MshFile(*text, "text").text() == *text, "the same text");

  std::cout << "3. Formats 2.2 and 4.1 alike\n";
  {
    Triangulation<2> a, b;
    create_triangulation(MshFile(block_2, "2.2"), a);
    create_triangulation(MshFile(block_4, "4.1"), b);
    expect(same(a, b), "the same triangulation");
  }

  std::cout << "4. Splitting along a curve\n";
  {
    const MshFile mesh(patch, "interface-patch.geo");
    const MshFile split = split_along_curves(mesh, {3});
    std::cout << "  nodes " << mesh.node_ids.size() << " -> "
              << split.node_ids.size() << ", lines of curve 3 "
              << count(mesh, 1, 3) << " -> " << count(split, 1, 3) << ", cells "
              << count(mesh, 3, -1) << " -> " << count(split, 3, -1) << '\n';
    expect(split.node_ids.size() == mesh.node_ids.size() + 5, "5 copies");
    expect(count(mesh, 1, 3) == 4 && count(split, 1, 3) == 8,
           "each line of the curve twice");
    expect(count(split, 3, -1) == count(mesh, 3, -1), "the cells kept");

    Triangulation<2> tria;
    create_triangulation(split, tria);
    unsigned int n_faces = 0, n_pairs = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 3)
          {
            ++n_faces;
            if (cell->center()[1] > 0)
              for (const auto &other : tria.active_cell_iterators())
                for (const auto g : other->face_indices())
                  if (other->center()[1] < 0 && other->face(g)->at_boundary() &&
                      other->face(g)->boundary_id() == 3 &&
                      other->face(g)->center().distance(
                        cell->face(f)->center()) < 1e-12)
                    ++n_pairs;
          }
    std::cout << "  faces of curve 3: " << n_faces << ", facing pairs "
              << n_pairs << '\n';
    expect(n_faces == 8 && n_pairs == 4, "4 facing pairs");

    bool refused = false;
    try
      {
        split_along_curves(mesh, {1});
      }
    catch (const InputError &e)
      {
        refused = true;
        std::cout << "  along the bottom: " << e.what() << '\n';
      }
    expect(refused, "a curve on the boundary is refused");
  }

  std::cout << "5. Splitting along a surface\n";
  {
    // The two blocks of interface-patch.geo extruded, 2 elements deep: the
    // surface y = 0 reaches the boundary all round, so each of its
    // (4 + 1) x (2 + 1) nodes gets a copy.
    const MshFile mesh(gmsh("interface-patch-3d.geo", {}, 3),
                       "interface-patch-3d.geo");
    const MshFile split = split_along_curves(mesh, {3});
    std::cout << "  nodes " << mesh.node_ids.size() << " -> "
              << split.node_ids.size() << ", quadrilaterals of surface 3 "
              << count(mesh, 3, 3) << " -> " << count(split, 3, 3)
              << ", hexahedra " << count(mesh, 5, -1) << " -> "
              << count(split, 5, -1) << '\n';
    expect(split.node_ids.size() == mesh.node_ids.size() + 15, "15 copies");
    expect(count(mesh, 3, 3) == 8 && count(split, 3, 3) == 16,
           "each quadrilateral of the surface twice");
    expect(count(split, 5, -1) == count(mesh, 5, -1), "the cells kept");
    expect(as_deal_ii_reads<3>(split.text(), "interface-patch-3d.geo split"),
           "deal.II reads it alike");

    // Four hexahedra, 2 x 2 in x-y, one deep; the surface is the face
    // y = 1 between the two with x < 1 alone, so it ends at x = 1 inside
    // the body (a crack front): the nodes there stay joined, the two at
    // x = 0 are copied.
    std::ostringstream msh;
    msh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n18\n";
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          msh << 1 + i + 3 * j + 9 * k << ' ' << i << ' ' << j << ' ' << k
              << '\n';
    const auto node = [](const int i, const int j, const int k) {
      return 1 + i + 3 * j + 9 * k;
    };
    msh << "$EndNodes\n$Elements\n5\n1 3 2 3 3 " << node(0, 1, 0) << ' '
        << node(1, 1, 0) << ' ' << node(1, 1, 1) << ' ' << node(0, 1, 1)
        << '\n';
    for (int c = 0; c < 4; ++c)
      {
        const int i = c % 2, j = c / 2;
        msh << 2 + c << " 5 2 1 1";
        for (int k = 0; k < 2; ++k)
          msh << ' ' << node(i, j, k) << ' ' << node(i + 1, j, k) << ' '
              << node(i + 1, j + 1, k) << ' ' << node(i, j + 1, k);
        msh << '\n';
      }
    msh << "$EndElements\n";
    const MshFile front(msh.str(), "front.msh");
    const MshFile cut = split_along_curves(front, {3});
    std::cout << "  a surface ending inside the body: nodes "
              << front.node_ids.size() << " -> " << cut.node_ids.size() << '\n';
    expect(cut.node_ids.size() == 20, "the 2 nodes on the boundary copied");
    expect(count(cut, 3, 3) == 2, "the quadrilateral twice");
    Triangulation<3> tria;
    create_triangulation(cut, tria);
    unsigned int n_faces = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        n_faces +=
          cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 3;
    expect(n_faces == 2, "deal.II sees both sides as boundary faces");
  }

  std::cout << "6. Repeated corners\n";
  {
    std::string bad = block_2;
    bad.replace(bad.find("5 3 2 7 1 1 2 5 4"), 17, "5 3 2 7 1 1 2 2 4");
    const std::string found = repeated_corner(MshFile(bad, "bad"));
    std::cout << "  " << found << '\n';
    expect(found.find("element 5") != std::string::npos &&
             found.find("node 2 twice") != std::string::npos,
           "element 5 names node 2 twice");
    expect(repeated_corner(MshFile(block_2, "good")).empty(), "none");
  }
  return truths::conclude();
}
