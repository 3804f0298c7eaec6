#include <thinlayer/input_error.h>
#include <thinlayer/mesh_splitting.h>

#include <algorithm>
#include <array>
#include <map>
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
  } // namespace


  std::string
  split_along_curves(const std::string            &msh,
                     const std::set<unsigned int> &curves,
                     const std::string            &mesh_file)
  {
    if (curves.empty())
      return msh;
    const auto fail = [&](const std::string &what) {
      throw InputError(mesh_file, "", what);
    };
    if (msh.find("$MeshFormat\n2.2") == std::string::npos)
      fail("a gmsh mesh in format 2.2 for interface curves (gmsh -format "
           "msh22); .geo files are meshed so");

    std::size_t        nodes_begin, nodes_end, elements_begin, elements_end;
    std::istringstream node_text(
      section(msh, "$Nodes\n", "$EndNodes", nodes_begin, nodes_end));
    std::istringstream element_text(section(
      msh, "$Elements\n", "$EndElements", elements_begin, elements_end));

    // Nodes: id -> coordinates, and the text after the id (to copy).
    std::map<long, std::array<double, 2>> position;
    std::map<long, std::string>           coordinates;
    std::size_t                           n_nodes = 0;
    node_text >> n_nodes;
    long max_node = 0;
    for (std::size_t i = 0; i < n_nodes; ++i)
      {
        long        id;
        double      x, y;
        std::string rest;
        node_text >> id;
        std::getline(node_text, rest);
        std::istringstream(rest) >> x >> y;
        position[id]    = {{x, y}};
        coordinates[id] = rest;
        max_node        = std::max(max_node, id);
      }

    std::vector<MshElement> elements;
    std::size_t             n_elements = 0;
    element_text >> n_elements;
    long max_element = 0;
    for (std::size_t i = 0; i < n_elements; ++i)
      {
        MshElement e;
        int        n_tags;
        element_text >> e.id >> e.type >> n_tags;
        e.tags.resize(n_tags);
        for (auto &t : e.tags)
          element_text >> t;
        const int n = e.type == 1 ? 2 : e.type == 3 ? 4 : e.type == 15 ? 1 : -1;
        if (n < 0)
          fail("first-order quadrilaterals and lines for interface curves "
               "(gmsh element types 1, 3 and 15); element " +
               std::to_string(e.id) + " is of type " + std::to_string(e.type));
        e.nodes.resize(n);
        for (auto &v : e.nodes)
          element_text >> v;
        max_element = std::max(max_element, e.id);
        elements.push_back(e);
      }
    if (!element_text)
      fail("a readable $Elements section");

    const auto is_curve_line = [&](const MshElement &e) {
      return e.type == 1 && !e.tags.empty() &&
             curves.count(static_cast<unsigned int>(e.tags[0])) != 0;
    };

    // Cells beside every edge, and cells around every node.
    std::map<Edge, std::vector<std::size_t>> cells_of_edge;
    std::map<long, std::vector<std::size_t>> cells_of_node;
    for (std::size_t k = 0; k < elements.size(); ++k)
      if (elements[k].type == 3)
        {
          for (const Edge &e : quad_edges(elements[k].nodes))
            cells_of_edge[e].push_back(k);
          for (const long v : elements[k].nodes)
            cells_of_node[v].push_back(k);
        }

    // The curves' edges, their left and right cells, and per node the
    // cells that start each side's fan.
    std::map<Edge, unsigned int>             curve_edge;
    std::map<long, std::vector<std::size_t>> left_seeds, right_seeds;
    std::map<long, unsigned int>             edges_at_node;
    for (const MshElement &line : elements)
      if (is_curve_line(line))
        {
          const long a = line.nodes[0], b = line.nodes[1];
          const auto beside = cells_of_edge[edge(a, b)];
          if (beside.size() != 2)
            {
              std::ostringstream message;
              message << "physical curve " << line.tags[0]
                      << " of interface elements to run through the body, "
                         "with a cell on each side; its line from ("
                      << position[a][0] << ", " << position[a][1] << ") to ("
                      << position[b][0] << ", " << position[b][1] << ") has "
                      << beside.size();
              fail(message.str());
            }
          curve_edge[edge(a, b)] = line.tags[0];
          for (const std::size_t k : beside)
            {
              double cx = 0, cy = 0;
              for (const long v : elements[k].nodes)
                {
                  cx += position[v][0] / 4;
                  cy += position[v][1] / 4;
                }
              const double cross =
                (position[b][0] - position[a][0]) * (cy - position[a][1]) -
                (position[b][1] - position[a][1]) * (cx - position[a][0]);
              for (const long v : {a, b})
                (cross > 0 ? left_seeds : right_seeds)[v].push_back(k);
            }
          for (const long v : {a, b})
            if (++edges_at_node[v] > 2)
              {
                std::ostringstream message;
                message << "interface curves that neither branch nor meet; "
                           "three or more of their lines meet at ("
                        << position[v][0] << ", " << position[v][1] << ")";
                fail(message.str());
              }
        }

    // Each node's left fan: the cells around it reached from its left seeds
    // without crossing a curve. If the fan reaches a right seed, the curve
    // ends inside the body there (a tip): the node stays shared.
    std::map<long, long> duplicate;
    for (const auto &[v, seeds] : left_seeds)
      {
        const auto              &around = cells_of_node[v];
        std::vector<bool>        in_fan(around.size(), false);
        std::vector<std::size_t> queue;
        for (std::size_t i = 0; i < around.size(); ++i)
          if (std::count(seeds.begin(), seeds.end(), around[i]))
            {
              in_fan[i] = true;
              queue.push_back(i);
            }
        while (!queue.empty())
          {
            const std::size_t i = queue.back();
            queue.pop_back();
            for (const Edge &e : quad_edges(elements[around[i]].nodes))
              if ((e.first == v || e.second == v) && !curve_edge.count(e))
                for (std::size_t j = 0; j < around.size(); ++j)
                  if (!in_fan[j])
                    {
                      const auto edges = quad_edges(elements[around[j]].nodes);
                      if (std::find(edges.begin(), edges.end(), e) !=
                          edges.end())
                        {
                          in_fan[j] = true;
                          queue.push_back(j);
                        }
                    }
          }
        bool tip = false;
        for (std::size_t i = 0; i < around.size(); ++i)
          if (in_fan[i] && std::count(right_seeds[v].begin(),
                                      right_seeds[v].end(),
                                      around[i]))
            tip = true;
        if (tip)
          continue;
        const long copy   = ++max_node;
        duplicate[v]      = copy;
        position[copy]    = position[v];
        coordinates[copy] = coordinates[v];
        for (std::size_t i = 0; i < around.size(); ++i)
          if (in_fan[i])
            std::replace(elements[around[i]].nodes.begin(),
                         elements[around[i]].nodes.end(),
                         v,
                         copy);
      }

    // Lines: a curve's line is repeated with the left side's nodes; any
    // other line whose nodes were copied follows the cell it bounds.
    std::map<Edge, bool> renumbered_cell_edge;
    for (const MshElement &e : elements)
      if (e.type == 3)
        for (const Edge &edge_of_cell : quad_edges(e.nodes))
          renumbered_cell_edge[edge_of_cell] = true;
    const auto copied = [&](const long v) {
      const auto it = duplicate.find(v);
      return it == duplicate.end() ? v : it->second;
    };
    std::vector<MshElement> added;
    for (MshElement &e : elements)
      if (e.type == 1)
        {
          MshElement left = e;
          left.nodes      = {copied(e.nodes[0]), copied(e.nodes[1])};
          if (left.nodes == e.nodes)
            continue;
          if (is_curve_line(e))
            {
              left.id = ++max_element;
              added.push_back(left);
            }
          else if (renumbered_cell_edge.count(
                     edge(left.nodes[0], left.nodes[1])) &&
                   !renumbered_cell_edge.count(edge(e.nodes[0], e.nodes[1])))
            e.nodes = left.nodes;
        }
    elements.insert(elements.end(), added.begin(), added.end());

    std::ostringstream out;
    out << msh.substr(0, nodes_begin) << "$Nodes\n" << position.size() << '\n';
    for (const auto &[id, text] : coordinates)
      out << id << text << '\n';
    out << "$EndNodes" << msh.substr(nodes_end, elements_begin - nodes_end)
        << "$Elements\n"
        << elements.size() << '\n';
    for (const MshElement &e : elements)
      {
        out << e.id << ' ' << e.type << ' ' << e.tags.size();
        for (const long t : e.tags)
          out << ' ' << t;
        for (const long v : e.nodes)
          out << ' ' << v;
        out << '\n';
      }
    out << "$EndElements" << msh.substr(elements_end);
    return out.str();
  }
} // namespace thinlayer
