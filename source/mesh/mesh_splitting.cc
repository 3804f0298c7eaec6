#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/mesh_splitting.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace thinlayer
{
  namespace
  {
    struct MshElement
    {
      long              id;
      int               type;
      std::vector<long> tags;
      std::vector<long> nodes;
    };

    using Edge = std::pair<long, long>;

    Edge
    edge(const long a, const long b)
    {
      return {std::min(a, b), std::max(a, b)};
    }

    /// The edges of a quadrilateral (nodes in order around it).
    std::array<Edge, 4>
    quad_edges(const std::vector<long> &n)
    {
      return {{edge(n[0], n[1]),
               edge(n[1], n[2]),
               edge(n[2], n[3]),
               edge(n[3], n[0])}};
    }

    /// The text between @p open and @p close in @p msh, and where it lies.
    std::string
    section(const std::string &msh,
            const std::string &open,
            const std::string &close,
            std::size_t       &begin,
            std::size_t       &end)
    {
      begin = msh.find(open);
      end   = msh.find(close, begin);
      if (begin == std::string::npos || end == std::string::npos)
        return "";
      const std::size_t start = begin + open.size();
      end += close.size();
      return msh.substr(start, end - close.size() - start);
    }

    /// A gmsh 2.2 mesh: its nodes and elements, and the text around them.
    struct Msh
    {
      std::string before_nodes, between, after_elements;
      std::map<long, std::array<double, 2>> position;
      /// The text after each node's id, copied as it is.
      std::map<long, std::string> coordinates;
      long                        max_node = 0;
      std::vector<MshElement>     elements;
      long                        max_element = 0;
    };


    [[noreturn]] void
    fail(const std::string &mesh_file, const std::string &what)
    {
      throw InputError(mesh_file, "", what);
    }


    Msh
    read_msh2(const std::string &msh, const std::string &mesh_file)
    {
      if (msh.find("$MeshFormat\n2.2") == std::string::npos)
        fail(mesh_file,
             "a gmsh mesh in format 2.2 for interface curves (gmsh -format "
             "msh22); .geo files are meshed so");
      Msh                mesh;
      std::size_t        nodes_begin, nodes_end, elements_begin, elements_end;
      std::istringstream node_text(
        section(msh, "$Nodes\n", "$EndNodes", nodes_begin, nodes_end));
      std::istringstream element_text(section(
        msh, "$Elements\n", "$EndElements", elements_begin, elements_end));
      mesh.before_nodes   = msh.substr(0, nodes_begin);
      mesh.between        = msh.substr(nodes_end, elements_begin - nodes_end);
      mesh.after_elements = msh.substr(elements_end);

      std::size_t n_nodes = 0;
      node_text >> n_nodes;
      for (std::size_t i = 0; i < n_nodes; ++i)
        {
          long        id;
          double      x, y;
          std::string rest;
          node_text >> id;
          std::getline(node_text, rest);
          std::istringstream(rest) >> x >> y;
          mesh.position[id]    = {{x, y}};
          mesh.coordinates[id] = rest;
          mesh.max_node        = std::max(mesh.max_node, id);
        }

      std::size_t n_elements = 0;
      element_text >> n_elements;
      for (std::size_t i = 0; i < n_elements; ++i)
        {
          MshElement e;
          int        n_tags;
          element_text >> e.id >> e.type >> n_tags;
          e.tags.resize(n_tags);
          for (auto &t : e.tags)
            element_text >> t;
          const int n = e.type == 1    ? 2
                        : e.type == 3  ? 4
                        : e.type == 15 ? 1
                                       : -1;
          if (n < 0)
            fail(mesh_file,
                 "first-order quadrilaterals and lines for interface curves "
                 "(gmsh element types 1, 3 and 15); element " +
                   std::to_string(e.id) + " is of type " +
                   std::to_string(e.type));
          e.nodes.resize(n);
          for (auto &v : e.nodes)
            element_text >> v;
          mesh.max_element = std::max(mesh.max_element, e.id);
          mesh.elements.push_back(e);
        }
      if (!element_text)
        fail(mesh_file, "a readable $Elements section");
      return mesh;
    }


    std::string
    write_msh2(const Msh &mesh)
    {
      std::ostringstream out;
      out << mesh.before_nodes << "$Nodes\n" << mesh.coordinates.size() << '\n';
      for (const auto &[id, text] : mesh.coordinates)
        out << id << text << '\n';
      out << "$EndNodes" << mesh.between << "$Elements\n"
          << mesh.elements.size() << '\n';
      for (const MshElement &e : mesh.elements)
        {
          out << e.id << ' ' << e.type << ' ' << e.tags.size();
          for (const long t : e.tags)
            out << ' ' << t;
          for (const long v : e.nodes)
            out << ' ' << v;
          out << '\n';
        }
      out << "$EndElements" << mesh.after_elements;
      return out.str();
    }


    /// The cells of a mesh beside every edge and around every node.
    struct Adjacency
    {
      std::map<Edge, std::vector<std::size_t>> cells_of_edge;
      std::map<long, std::vector<std::size_t>> cells_of_node;

      explicit Adjacency(const std::vector<MshElement> &elements)
      {
        for (std::size_t k = 0; k < elements.size(); ++k)
          if (elements[k].type == 3)
            {
              for (const Edge &e : quad_edges(elements[k].nodes))
                cells_of_edge[e].push_back(k);
              for (const long v : elements[k].nodes)
                cells_of_node[v].push_back(k);
            }
      }
    };


    /// The curves' edges, each checked to have a cell on either side.
    std::map<Edge, unsigned int>
    curve_edges(const Msh                                     &mesh,
                const Adjacency                               &adjacency,
                const std::function<bool(const MshElement &)> &is_curve_line,
                const std::string                             &mesh_file)
    {
      std::map<Edge, unsigned int> edges;
      for (const MshElement &line : mesh.elements)
        if (is_curve_line(line))
          {
            const long a = line.nodes[0], b = line.nodes[1];
            const auto found = adjacency.cells_of_edge.find(edge(a, b));
            const auto beside =
              found == adjacency.cells_of_edge.end() ? 0 : found->second.size();
            if (beside != 2)
              {
                const auto        &pa = mesh.position.at(a);
                const auto        &pb = mesh.position.at(b);
                std::ostringstream message;
                message << "physical curve " << line.tags[0]
                        << " of interface elements to run through the body, "
                           "with a cell on each side; its line from ("
                        << pa[0] << ", " << pa[1] << ") to (" << pb[0] << ", "
                        << pb[1] << ") has " << beside;
                fail(mesh_file, message.str());
              }
            edges[edge(a, b)] = line.tags[0];
          }
      return edges;
    }


    /**
     * Around node @p v, the curves' edges part the cells into sectors
     * (cells joined through edges at the node that are not on a curve).
     * Every sector but the first gets its own copy of the node, in
     * @p mesh's cells; a node with one sector (a curve's end inside the
     * body) stays shared. @p original is the mesh's cells before any copy.
     */
    void
    copy_node_per_sector(Msh                                &mesh,
                         const std::vector<MshElement>      &original,
                         const Adjacency                    &adjacency,
                         const std::map<Edge, unsigned int> &curve_edge,
                         const long                          v)
    {
      const auto      &around = adjacency.cells_of_node.at(v);
      std::vector<int> sector(around.size(), -1);
      int              n_sectors = 0;
      for (std::size_t start = 0; start < around.size(); ++start)
        if (sector[start] < 0)
          {
            std::vector<std::size_t> queue = {start};
            sector[start]                  = n_sectors;
            while (!queue.empty())
              {
                const std::size_t i = queue.back();
                queue.pop_back();
                for (const Edge &e : quad_edges(original[around[i]].nodes))
                  if ((e.first == v || e.second == v) && !curve_edge.count(e))
                    for (std::size_t j = 0; j < around.size(); ++j)
                      if (sector[j] < 0)
                        {
                          const auto edges =
                            quad_edges(original[around[j]].nodes);
                          if (std::find(edges.begin(), edges.end(), e) !=
                              edges.end())
                            {
                              sector[j] = n_sectors;
                              queue.push_back(j);
                            }
                        }
              }
            ++n_sectors;
          }
      std::vector<long> copy_of_sector(n_sectors, v);
      for (int k = 1; k < n_sectors; ++k)
        {
          copy_of_sector[k]                   = ++mesh.max_node;
          mesh.coordinates[copy_of_sector[k]] = mesh.coordinates[v];
          mesh.position[copy_of_sector[k]]    = mesh.position[v];
        }
      for (std::size_t i = 0; i < around.size(); ++i)
        std::replace(mesh.elements[around[i]].nodes.begin(),
                     mesh.elements[around[i]].nodes.end(),
                     v,
                     copy_of_sector[sector[i]]);
    }


    /**
     * The lines after the copies: each takes the nodes of the cell beside
     * it; a curve's line becomes two, one for each side's cell.
     */
    void
    relabel_lines(Msh                                           &mesh,
                  const std::vector<MshElement>                 &original,
                  const Adjacency                               &adjacency,
                  const std::function<bool(const MshElement &)> &is_curve_line)
    {
      const auto nodes_in_cell = [&](const std::size_t cell, const long v) {
        const auto &before = original[cell].nodes;
        return mesh.elements[cell]
          .nodes[std::find(before.begin(), before.end(), v) - before.begin()];
      };
      std::vector<MshElement> lines;
      for (const MshElement &e : original)
        if (e.type == 1)
          {
            const auto found =
              adjacency.cells_of_edge.find(edge(e.nodes[0], e.nodes[1]));
            if (found == adjacency.cells_of_edge.end())
              {
                lines.push_back(e);
                continue;
              }
            const auto &beside = found->second;
            for (std::size_t k = 0; k < beside.size(); ++k)
              {
                MshElement line = e;
                line.nodes      = {nodes_in_cell(beside[k], e.nodes[0]),
                                   nodes_in_cell(beside[k], e.nodes[1])};
                if (k > 0)
                  {
                    if (!is_curve_line(e))
                      break;
                    line.id = ++mesh.max_element;
                  }
                lines.push_back(line);
              }
          }
      std::vector<MshElement> result;
      for (const MshElement &e : mesh.elements)
        if (e.type != 1)
          result.push_back(e);
      result.insert(result.end(), lines.begin(), lines.end());
      mesh.elements = result;
    }
  } // namespace


  std::string
  split_along_curves(const std::string            &msh,
                     const std::set<unsigned int> &curves,
                     const std::string            &mesh_file)
  {
    if (curves.empty())
      return msh;
    Msh                           mesh     = read_msh2(msh, mesh_file);
    const std::vector<MshElement> original = mesh.elements;
    const Adjacency               adjacency(original);
    const auto                    is_curve_line = [&](const MshElement &e) {
      return e.type == 1 && !e.tags.empty() &&
             curves.count(static_cast<unsigned int>(e.tags[0])) != 0;
    };
    const std::map<Edge, unsigned int> curve_edge =
      curve_edges(mesh, adjacency, is_curve_line, mesh_file);
    std::set<long> curve_nodes;
    for (const auto &[e, curve] : curve_edge)
      {
        curve_nodes.insert(e.first);
        curve_nodes.insert(e.second);
      }
    for (const long v : curve_nodes)
      copy_node_per_sector(mesh, original, adjacency, curve_edge, v);
    relabel_lines(mesh, original, adjacency, is_curve_line);
    return write_msh2(mesh);
  }
} // namespace thinlayer
