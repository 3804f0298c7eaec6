#ifndef thinlayer_mesh_msh_file_h
#define thinlayer_mesh_msh_file_h

#include <deal.II/grid/tria.h>

#include <array>
#include <string>
#include <vector>

namespace thinlayer
{
  using namespace dealii;

  /// One element of a gmsh mesh: its number, gmsh type, tags (the
  /// physical tag first) and nodes, as in the file.
  struct MshElement
  {
    long              id;
    int               type;
    std::vector<long> tags;
    std::vector<long> nodes;

    /// The physical tag (0 where the element has none).
    long
    physical() const
    {
      return tags.empty() ? 0 : tags[0];
    }
  };


  /**
   * A gmsh mesh, read once from its text (ASCII format 2.2, as thinlayer
   * has gmsh write it, or 4.1) and shared by everything that looks at the
   * mesh: the checks of its elements, the splitting along interface curves
   * (split_along_curves()), and the triangulation (create_triangulation()).
   *
   * The nodes and elements are kept in the file's order; of a file in
   * format 2.2 the text around the $Nodes and $Elements sections is kept
   * too, and each node's coordinates as written, so that a mesh that was
   * split is written back (text()) with every number as gmsh wrote it.
   */
  struct MshFile
  {
    /// Read @p text; InputError (naming @p file) where it is no gmsh mesh
    /// in ASCII format 2.2 or 4.1, or a section cannot be read.
    MshFile(const std::string &text, const std::string &file);

    /// The mesh as text in format 2.2: nodes sorted by number.
    std::string
    text() const;

    /// Whether the file was in format 2.2.
    bool
    is_version_2() const;

    /// The number of nodes of a gmsh element type; -1 for a type this
    /// reader does not know.
    static int
    n_nodes(const int type);

    std::string file;
    double      version = 0;

    std::vector<long>                  node_ids;
    std::vector<std::array<double, 3>> positions;
    /// Format 2.2: each node's line after its number, as written.
    std::vector<std::string> node_text;

    std::vector<MshElement> elements;

    /// Format 2.2: the text before $Nodes, between $EndNodes and
    /// $Elements, and after $EndElements.
    std::string before_nodes, between, after_elements;
  };


  /**
   * The triangulation of the cells of @p mesh (quadrilaterals in 2D,
   * hexahedra in 3D; their physical tags the material ids), with the
   * physical tags of its lines (2D and 3D) and quadrilateral faces (3D) as
   * boundary ids, built as deal.II's gmsh reader builds it: the same
   * vertex order, unused vertices removed, inverted cells turned, cells
   * consistently ordered. Throws InputError (naming the mesh file) for a
   * mesh without cells, with cells of another shape, with an element that
   * names a node the mesh does not have, or one that deal.II refuses (a
   * boundary id on an interior face: a physical curve through the body
   * that is not split for interface elements).
   */
  template <int dim>
  void
  create_triangulation(const MshFile &mesh, Triangulation<dim> &tria);


  /**
   * A quadrilateral (or hexahedron) of @p mesh that names the same node
   * twice among its corners: deal.II cannot build such a cell (its debug
   * library stops on it, its release library goes on with a cell of zero
   * area), so it is found here first. Returns a description of the first,
   * or an empty string.
   */
  std::string
  repeated_corner(const MshFile &mesh);
} // namespace thinlayer

#endif
