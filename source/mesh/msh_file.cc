#include <deal.II/grid/grid_tools.h>

#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/msh_file.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace thinlayer
{
  namespace
  {
    [[noreturn]] void
    fail(const std::string &file, const std::string &what)
    {
      throw InputError(file, "", "cannot read the mesh: " + what);
    }


    /// The text between @p open and @p close in @p text (empty if either
    /// is missing), and where the two lie.
    std::string
    section(const std::string &text,
            const std::string &open,
            const std::string &close,
            std::size_t       &begin,
            std::size_t       &end)
    {
      begin = text.find(open);
      end   = begin == std::string::npos ? begin : text.find(close, begin);
      if (begin == std::string::npos || end == std::string::npos)
        return "";
      const std::size_t start = begin + open.size();
      end += close.size();
      return text.substr(start, end - close.size() - start);
    }


    /// Whether @p text is three finite numbers, each written whole (not
    /// "abc", "nan" or "1junk"), read into @p x.
    bool
    read_coordinates(const std::string &text, std::array<double, 3> &x)
    {
      std::istringstream words(text);
      std::string        word;
      unsigned int       n = 0;
      while (words >> word)
        {
          if (n == 3)
            return false;
          try
            {
              std::size_t used = 0;
              x[n]             = std::stod(word, &used);
              if (used != word.size() || !std::isfinite(x[n]))
                return false;
            }
          catch (const std::exception &)
            {
              return false;
            }
          ++n;
        }
      return n == 3;
    }


    /// The nodes and elements of format 2.2.
    void
    read_version_2(const std::string &text, MshFile &mesh)
    {
      std::size_t        nodes_begin, nodes_end, elements_begin, elements_end;
      std::istringstream nodes(
        section(text, "$Nodes\n", "$EndNodes", nodes_begin, nodes_end));
      std::istringstream elements(section(
        text, "$Elements\n", "$EndElements", elements_begin, elements_end));
      if (nodes_end == std::string::npos || elements_end == std::string::npos)
        fail(mesh.file, "expected a $Nodes and an $Elements section");
      mesh.before_nodes   = text.substr(0, nodes_begin);
      mesh.between        = text.substr(nodes_end, elements_begin - nodes_end);
      mesh.after_elements = text.substr(elements_end);

      std::size_t n_nodes = 0;
      nodes >> n_nodes;
      for (std::size_t i = 0; i < n_nodes && nodes; ++i)
        {
          long        id = 0;
          std::string rest;
          nodes >> id;
          std::getline(nodes, rest);
          if (!nodes)
            break;
          std::array<double, 3> x{{0, 0, 0}};
          if (!read_coordinates(rest, x))
            fail(mesh.file,
                 "node " + std::to_string(id) + " has the coordinates '" +
                   Utilities::trim(rest) + "'; expected three finite numbers");
          mesh.node_ids.push_back(id);
          mesh.positions.push_back(x);
          mesh.node_text.push_back(rest);
        }
      if (!nodes)
        fail(mesh.file,
             "expected " + std::to_string(n_nodes) +
               " nodes in the $Nodes section");

      std::size_t n_elements = 0;
      elements >> n_elements;
      for (std::size_t i = 0; i < n_elements && elements; ++i)
        {
          MshElement e;
          int        n_tags = 0;
          elements >> e.id >> e.type >> n_tags;
          const int n = MshFile::n_nodes(e.type);
          if (elements && n < 0)
            fail(mesh.file,
                 "element " + std::to_string(e.id) + " is of gmsh type " +
                   std::to_string(e.type) +
                   ", which thinlayer does not read; expected lines, "
                   "quadrilaterals and hexahedra (types 1, 3 and 5)");
          e.tags.resize(std::max(n_tags, 0));
          for (auto &t : e.tags)
            elements >> t;
          e.nodes.resize(std::max(n, 0));
          for (auto &v : e.nodes)
            elements >> v;
          mesh.elements.push_back(e);
        }
      if (!elements)
        fail(mesh.file,
             "expected " + std::to_string(n_elements) +
               " elements in the $Elements section");
    }


    /// The first physical tag of every entity of format 4.1, by dimension
    /// and entity tag (0 for an entity without one).
    std::array<std::map<long, long>, 4>
    entity_physicals(const std::string &text, const std::string &file)
    {
      std::array<std::map<long, long>, 4> physicals;
      std::size_t                         begin, end;
      std::istringstream                  in(
        section(text, "$Entities\n", "$EndEntities", begin, end));
      if (end == std::string::npos)
        return physicals;
      std::array<long, 4> counts{{0, 0, 0, 0}};
      in >> counts[0] >> counts[1] >> counts[2] >> counts[3];
      for (unsigned int d = 0; d < 4; ++d)
        for (long k = 0; k < counts[d] && in; ++k)
          {
            long   tag, n_physicals, physical = 0, n_bounding, skip;
            double box;
            in >> tag;
            for (unsigned int i = 0; i < (d == 0 ? 3u : 6u); ++i)
              in >> box;
            in >> n_physicals;
            for (long i = 0; i < n_physicals; ++i)
              in >> (i == 0 ? physical : skip);
            physicals[d][tag] = physical;
            if (d > 0)
              {
                in >> n_bounding;
                for (long i = 0; i < n_bounding; ++i)
                  in >> skip;
              }
          }
      if (!in)
        fail(file, "expected a readable $Entities section");
      return physicals;
    }


    /// The nodes and elements of format 4.1.
    void
    read_version_4(const std::string &text, MshFile &mesh)
    {
      const auto         physicals = entity_physicals(text, mesh.file);
      std::size_t        nodes_begin, nodes_end, elements_begin, elements_end;
      std::istringstream nodes(
        section(text, "$Nodes\n", "$EndNodes", nodes_begin, nodes_end));
      std::istringstream elements(section(
        text, "$Elements\n", "$EndElements", elements_begin, elements_end));
      if (nodes_end == std::string::npos || elements_end == std::string::npos)
        fail(mesh.file, "expected a $Nodes and an $Elements section");

      long n_blocks = 0, n_total = 0, min_tag, max_tag;
      nodes >> n_blocks >> n_total >> min_tag >> max_tag;
      for (long b = 0; b < n_blocks && nodes; ++b)
        {
          int  entity_dim, entity, parametric;
          long n = 0;
          nodes >> entity_dim >> entity >> parametric >> n;
          for (long i = 0; i < n; ++i)
            {
              long id = 0;
              nodes >> id;
              mesh.node_ids.push_back(id);
            }
          for (long i = 0; i < n; ++i)
            {
              std::array<double, 3> x{{0, 0, 0}};
              nodes >> x[0] >> x[1] >> x[2];
              if (nodes && !(std::isfinite(x[0]) && std::isfinite(x[1]) &&
                             std::isfinite(x[2])))
                fail(mesh.file,
                     "a node has coordinates that are not finite numbers");
              double u;
              for (int k = 0; parametric != 0 && k < entity_dim; ++k)
                nodes >> u;
              mesh.positions.push_back(x);
            }
        }
      if (!nodes || long(mesh.node_ids.size()) != n_total)
        fail(mesh.file,
             "expected " + std::to_string(n_total) +
               " nodes in the $Nodes section");

      elements >> n_blocks >> n_total >> min_tag >> max_tag;
      for (long b = 0; b < n_blocks && elements; ++b)
        {
          int  entity_dim, entity, type;
          long n = 0;
          elements >> entity_dim >> entity >> type >> n;
          const int n_nodes = MshFile::n_nodes(type);
          if (elements && n_nodes < 0)
            fail(mesh.file,
                 "an element block of gmsh type " + std::to_string(type) +
                   ", which thinlayer does not read; expected lines, "
                   "quadrilaterals and hexahedra (types 1, 3 and 5)");
          // The entity's physical tag, 0 for one without.
          long physical = 0;
          if (entity_dim >= 0 && entity_dim < 4)
            if (const auto p = physicals[entity_dim].find(entity);
                p != physicals[entity_dim].end())
              physical = p->second;
          for (long i = 0; i < n && elements; ++i)
            {
              MshElement e;
              e.type = type;
              e.tags = {physical, entity};
              elements >> e.id;
              e.nodes.resize(n_nodes);
              for (auto &v : e.nodes)
                elements >> v;
              mesh.elements.push_back(e);
            }
        }
      if (!elements || long(mesh.elements.size()) != n_total)
        fail(mesh.file,
             "expected " + std::to_string(n_total) +
               " elements in the $Elements section");
    }
  } // namespace


  int
  MshFile::n_nodes(const int type)
  {
    // gmsh's element types: line, triangle, quadrilateral, tetrahedron,
    // hexahedron, prism, pyramid, their second-order forms, point.
    static const std::map<int, int> nodes = {{1, 2},
                                             {2, 3},
                                             {3, 4},
                                             {4, 4},
                                             {5, 8},
                                             {6, 6},
                                             {7, 5},
                                             {8, 3},
                                             {9, 6},
                                             {10, 9},
                                             {11, 10},
                                             {12, 27},
                                             {13, 18},
                                             {14, 14},
                                             {15, 1},
                                             {16, 8},
                                             {17, 20},
                                             {18, 15},
                                             {19, 13}};
    const auto                      found = nodes.find(type);
    return found == nodes.end() ? -1 : found->second;
  }


  MshFile::MshFile(const std::string &text, const std::string &file)
    : file(file)
  {
    std::size_t        begin, end;
    std::istringstream format(
      section(text, "$MeshFormat\n", "$EndMeshFormat", begin, end));
    int file_type = -1, data_size = 0;
    format >> version >> file_type >> data_size;
    if (end == std::string::npos || !format)
      fail(file, "expected a gmsh mesh (a $MeshFormat section first)");
    if (file_type != 0)
      fail(file,
           "a binary gmsh mesh; expected ASCII (Mesh.Binary = 0, or gmsh "
           "-format msh22)");
    if (version == 2.2)
      read_version_2(text, *this);
    else if (version == 4.1)
      read_version_4(text, *this);
    else
      fail(file,
           "a mesh in gmsh's format " + std::to_string(version).substr(0, 3) +
             "; expected format 2.2 or 4.1 (gmsh -format msh22)");

    std::vector<long> ids = node_ids;
    std::sort(ids.begin(), ids.end());
    if (const auto twice = std::adjacent_find(ids.begin(), ids.end());
        twice != ids.end())
      fail(file,
           "node " + std::to_string(*twice) +
             " is defined twice; expected each node number once");
    for (const MshElement &e : elements)
      if (e.physical() < 0 || e.physical() > 2147483647l)
        fail(file,
             "element " + std::to_string(e.id) + " has the physical tag " +
               std::to_string(e.physical()) +
               "; expected a physical group's tag, a whole number from 1 "
               "to 2147483647 (or 0, none)");
  }


  bool
  MshFile::is_version_2() const
  {
    return version == 2.2;
  }


  std::string
  MshFile::text() const
  {
    Assert(is_version_2(), ExcMessage("Only format 2.2 is written."));
    std::vector<std::size_t> order(node_ids.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [this](const auto a, const auto b) {
      return node_ids[a] < node_ids[b];
    });
    std::ostringstream out;
    out << before_nodes << "$Nodes\n" << node_ids.size() << '\n';
    for (const std::size_t k : order)
      out << node_ids[k] << node_text[k] << '\n';
    out << "$EndNodes" << between << "$Elements\n" << elements.size() << '\n';
    for (const MshElement &e : elements)
      {
        out << e.id << ' ' << e.type << ' ' << e.tags.size();
        for (const long t : e.tags)
          out << ' ' << t;
        for (const long v : e.nodes)
          out << ' ' << v;
        out << '\n';
      }
    out << "$EndElements" << after_elements;
    return out.str();
  }


  template <int dim>
  void
  create_triangulation(const MshFile &mesh, Triangulation<dim> &tria)
  {
    // Cells: quadrilaterals (3) in 2D, hexahedra (5) in 3D; their simplex
    // counterparts are refused. Boundary faces: lines (1) in 2D and 3D,
    // quadrilaterals in 3D. Points (15) carry nothing in 2D or 3D.
    const int         cell_type    = dim == 2 ? 3 : 5;
    const int         simplex_type = dim == 2 ? 2 : 4;
    const std::string shape =
      dim == 2 ? "quadrilateral cells only (use Recombine Surface or "
                 "Mesh.RecombineAll in the .geo)"
               : "hexahedral cells only (use Recombine in the .geo)";

    std::map<long, unsigned int> vertex_of_node;
    std::vector<Point<dim>>      vertices(mesh.node_ids.size());
    for (unsigned int k = 0; k < mesh.node_ids.size(); ++k)
      {
        for (unsigned int d = 0; d < dim; ++d)
          vertices[k][d] = mesh.positions[k][d];
        vertex_of_node[mesh.node_ids[k]] = k;
      }
    const auto vertex = [&](const MshElement &e, const long node) {
      const auto found = vertex_of_node.find(node);
      if (found == vertex_of_node.end())
        throw InputError(mesh.file,
                         "",
                         "element " + std::to_string(e.id) +
                           " (gmsh's numbering) names node " +
                           std::to_string(node) +
                           ", which the mesh does not have");
      return found->second;
    };

    std::vector<CellData<dim>> cells;
    SubCellData                subcells;
    for (const MshElement &e : mesh.elements)
      if (e.type == cell_type)
        {
          cells.emplace_back();
          for (unsigned int i = 0; i < e.nodes.size(); ++i)
            cells.back().vertices[GeometryInfo<dim>::ucd_to_deal[i]] =
              vertex(e, e.nodes[i]);
          cells.back().material_id = e.physical();
        }
      else if (e.type == simplex_type)
        throw InputError(mesh.file, "", "expected " + shape);
      else if (e.type == 1)
        {
          subcells.boundary_lines.emplace_back();
          for (unsigned int i = 0; i < 2; ++i)
            subcells.boundary_lines.back().vertices[i] = vertex(e, e.nodes[i]);
          subcells.boundary_lines.back().boundary_id = e.physical();
        }
      else if (e.type == 3 && dim == 3)
        {
          subcells.boundary_quads.emplace_back();
          for (unsigned int i = 0; i < 4; ++i)
            subcells.boundary_quads.back().vertices[i] = vertex(e, e.nodes[i]);
          subcells.boundary_quads.back().boundary_id = e.physical();
        }
      else if (e.type != 15)
        throw InputError(mesh.file,
                         "",
                         "element " + std::to_string(e.id) +
                           " (gmsh's numbering) is of gmsh type " +
                           std::to_string(e.type) + "; expected " + shape);
    if (cells.empty())
      throw InputError(mesh.file,
                       "",
                       "the mesh has no " + std::to_string(dim) +
                         "D cells: are all " +
                         (dim == 2 ? "surfaces" : "volumes") +
                         " in a physical group?");

    // deal.II's own checks (a boundary id on an interior face, cells that
    // cannot be oriented consistently) name the file like ours.
    try
      {
        GridTools::delete_unused_vertices(vertices, cells, subcells);
        GridTools::invert_all_negative_measure_cells(vertices, cells);
        GridTools::consistently_order_cells(cells);
        tria.create_triangulation(vertices, cells, subcells);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        fail(mesh.file, message.str());
      }
  }


  std::string
  repeated_corner(const MshFile &mesh)
  {
    // gmsh's quadrilaterals (4, 9 and 8 nodes) and hexahedra (8, 27, 20).
    const std::map<int, unsigned int> corners = {
      {3, 4}, {10, 4}, {16, 4}, {5, 8}, {12, 8}, {17, 8}};
    for (const MshElement &e : mesh.elements)
      if (const auto n = corners.find(e.type); n != corners.end())
        for (unsigned int i = 0; i < n->second; ++i)
          for (unsigned int j = i + 1; j < n->second; ++j)
            if (e.nodes[i] == e.nodes[j])
              return "element " + std::to_string(e.id) +
                     " (gmsh's numbering) names node " +
                     std::to_string(e.nodes[i]) + " twice among its corners";
    return "";
  }


  template void
  create_triangulation(const MshFile &, Triangulation<2> &);
  template void
  create_triangulation(const MshFile &, Triangulation<3> &);
} // namespace thinlayer
