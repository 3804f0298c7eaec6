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

    /// A gmsh 2.2 mesh being split: its nodes by number, and its elements.
    struct Msh
    {
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


    /// The nodes and elements of @p file, which must be in format 2.2
    /// with first-order quadrilaterals, lines and points only.
    Msh
    read_msh2(const MshFile &file)
    {
      if (!file.is_version_2())
        fail(file.file,
             "a gmsh mesh in format 2.2 for interface curves (gmsh -format "
             "msh22); .geo files are meshed so");
      Msh mesh;
      for (std::size_t k = 0; k < file.node_ids.size(); ++k)
        {
          const long id        = file.node_ids[k];
          mesh.position[id]    = {{file.positions[k][0], file.positions[k][1]}};
          mesh.coordinates[id] = file.node_text[k];
          mesh.max_node        = std::max(mesh.max_node, id);
        }
      for (const MshElement &e : file.elements)
        {
          if (e.type != 1 && e.type != 3 && e.type != 15)
            fail(file.file,
                 "first-order quadrilaterals and lines for interface curves "
                 "(gmsh element types 1, 3 and 15); element " +
                   std::to_string(e.id) + " is of type " +
                   std::to_string(e.type));
          mesh.max_element = std::max(mesh.max_element, e.id);
          mesh.elements.push_back(e);
        }
      return mesh;
    }


    /// @p file with the nodes and elements of @p mesh.
    MshFile
    with_nodes_and_elements(MshFile file, const Msh &mesh)
    {
      file.node_ids.clear();
      file.positions.clear();
      file.node_text.clear();
      for (const auto &[id, text] : mesh.coordinates)
        {
          const auto &x = mesh.position.at(id);
          file.node_ids.push_back(id);
          file.positions.push_back({{x[0], x[1], 0.}});
          file.node_text.push_back(text);
        }
      file.elements = mesh.elements;
      return file;
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


  MshFile
  split_along_curves(const MshFile &msh, const std::set<unsigned int> &curves)
  {
    if (curves.empty())
      return msh;
    const std::string            &mesh_file = msh.file;
    Msh                           mesh      = read_msh2(msh);
    const std::vector<MshElement> original  = mesh.elements;
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
    return with_nodes_and_elements(msh, mesh);
  }
} // namespace thinlayer
