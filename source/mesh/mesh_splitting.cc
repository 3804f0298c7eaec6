#include <thinlayer/base/input_error.h>
#include <thinlayer/mesh/mesh_splitting.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <vector>

namespace thinlayer
{
  namespace
  {
    /// A cell's side (a line's two nodes in 2D, a quadrilateral's four in
    /// 3D), sorted, so that the two cells beside it name it alike.
    using Facet = std::vector<long>;

    Facet
    facet(std::vector<long> nodes)
    {
      std::sort(nodes.begin(), nodes.end());
      return nodes;
    }


    /// The gmsh element types of a mesh of quadrilaterals (2D) or
    /// hexahedra (3D): its cells, and the sides an interface is made of.
    struct Shapes
    {
      int          cell;
      int          side;
      unsigned int dim;
      /// "curve" or "surface": what a physical group of sides is.
      const char *group;
    };

    constexpr Shapes shapes_2d = {3, 1, 2, "curve"};
    constexpr Shapes shapes_3d = {5, 3, 3, "surface"};


    /// The sides of a cell: a quadrilateral's four edges (nodes in order
    /// around it), a hexahedron's six faces (gmsh's node order: the
    /// bottom face 0-3, the top face 4-7 above it).
    std::vector<Facet>
    cell_sides(const std::vector<long> &n)
    {
      if (n.size() == 4)
        return {facet({n[0], n[1]}),
                facet({n[1], n[2]}),
                facet({n[2], n[3]}),
                facet({n[3], n[0]})};
      return {facet({n[0], n[1], n[2], n[3]}),
              facet({n[4], n[5], n[6], n[7]}),
              facet({n[0], n[1], n[5], n[4]}),
              facet({n[1], n[2], n[6], n[5]}),
              facet({n[2], n[3], n[7], n[6]}),
              facet({n[3], n[0], n[4], n[7]})};
    }


    /// A gmsh 2.2 mesh being split: its nodes by number, and its elements.
    struct Msh
    {
      std::map<long, std::array<double, 3>> position;
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
    /// with first-order quadrilaterals, lines and points (2D), or
    /// hexahedra with them (3D), only.
    Msh
    read_msh2(const MshFile &file, const Shapes &shapes)
    {
      if (!file.is_version_2())
        fail(file.file,
             std::string("a gmsh mesh in format 2.2 for interface ") +
               shapes.group +
               "s (gmsh -format msh22); .geo files are meshed so");
      Msh mesh;
      for (std::size_t k = 0; k < file.node_ids.size(); ++k)
        {
          const long id        = file.node_ids[k];
          mesh.position[id]    = file.positions[k];
          mesh.coordinates[id] = file.node_text[k];
          mesh.max_node        = std::max(mesh.max_node, id);
        }
      for (const MshElement &e : file.elements)
        {
          if (e.type != 1 && e.type != 3 && e.type != 15 &&
              e.type != shapes.cell)
            fail(file.file,
                 shapes.dim == 2
                   ? "first-order quadrilaterals and lines for interface "
                     "curves (gmsh element types 1, 3 and 15); element " +
                       std::to_string(e.id) + " is of type " +
                       std::to_string(e.type)
                   : "first-order hexahedra, quadrilaterals and lines for "
                     "interface surfaces (gmsh element types 1, 3, 5 and 15); "
                     "element " +
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
          file.node_ids.push_back(id);
          file.positions.push_back(mesh.position.at(id));
          file.node_text.push_back(text);
        }
      file.elements = mesh.elements;
      return file;
    }


    /// The cells of a mesh beside every side and around every node.
    struct Adjacency
    {
      std::map<Facet, std::vector<std::size_t>> cells_of_side;
      std::map<long, std::vector<std::size_t>>  cells_of_node;

      Adjacency(const std::vector<MshElement> &elements, const Shapes &shapes)
      {
        for (std::size_t k = 0; k < elements.size(); ++k)
          if (elements[k].type == shapes.cell)
            {
              for (const Facet &f : cell_sides(elements[k].nodes))
                cells_of_side[f].push_back(k);
              for (const long v : elements[k].nodes)
                cells_of_node[v].push_back(k);
            }
      }

      /// The cells that have every node of @p nodes.
      std::vector<std::size_t>
      cells_with(const std::vector<long> &nodes) const
      {
        const auto found = cells_of_node.find(nodes[0]);
        if (found == cells_of_node.end())
          return {};
        std::vector<std::size_t> result;
        for (const std::size_t cell : found->second)
          if (std::all_of(nodes.begin(), nodes.end(), [&](const long v) {
                const auto of_v = cells_of_node.find(v);
                return of_v != cells_of_node.end() &&
                       std::find(of_v->second.begin(),
                                 of_v->second.end(),
                                 cell) != of_v->second.end();
              }))
            result.push_back(cell);
        return result;
      }
    };


    /// The interface's sides, each checked to have a cell on either side.
    std::set<Facet>
    interface_sides(const Msh                                     &mesh,
                    const Adjacency                               &adjacency,
                    const Shapes                                  &shapes,
                    const std::function<bool(const MshElement &)> &on_interface,
                    const std::string                             &mesh_file)
    {
      std::set<Facet> sides;
      for (const MshElement &e : mesh.elements)
        if (on_interface(e))
          {
            const Facet f     = facet(e.nodes);
            const auto  found = adjacency.cells_of_side.find(f);
            const auto  beside =
              found == adjacency.cells_of_side.end() ? 0 : found->second.size();
            if (beside != 2)
              {
                std::ostringstream message;
                message << "physical " << shapes.group << ' ' << e.tags[0]
                        << " of interface elements to run through the body, "
                           "with a cell on each side; its "
                        << (shapes.dim == 2 ? "line" : "quadrilateral")
                        << " through";
                for (const long v : e.nodes)
                  {
                    const auto &x = mesh.position.at(v);
                    message << " (" << x[0] << ", " << x[1];
                    if (shapes.dim == 3)
                      message << ", " << x[2];
                    message << ')';
                  }
                message << " has " << beside;
                fail(mesh_file, message.str());
              }
            sides.insert(f);
          }
      return sides;
    }


    /// The root of @p k's set in the union-find forest @p parent.
    std::size_t
    root(std::vector<std::size_t> &parent, std::size_t k)
    {
      while (parent[k] != k)
        k = parent[k] = parent[parent[k]];
      return k;
    }


    /**
     * Around node @p v, the interface's sides part the cells into sectors
     * (cells joined through sides at the node that are not on the
     * interface). Every sector but the first gets its own copy of the node,
     * in @p mesh's cells; a node with one sector (where an interface ends
     * inside the body) stays shared. @p original is the mesh's cells before
     * any copy.
     */
    void
    copy_node_per_sector(Msh                           &mesh,
                         const std::vector<MshElement> &original,
                         const Adjacency               &adjacency,
                         const std::set<Facet>         &interface,
                         const long                     v)
    {
      const auto              &around = adjacency.cells_of_node.at(v);
      std::vector<std::size_t> parent(around.size());
      std::iota(parent.begin(), parent.end(), 0);
      std::map<Facet, std::size_t> first_beside;
      for (std::size_t i = 0; i < around.size(); ++i)
        for (const Facet &f : cell_sides(original[around[i]].nodes))
          if (std::binary_search(f.begin(), f.end(), v) && !interface.count(f))
            {
              const auto [it, inserted] = first_beside.emplace(f, i);
              if (!inserted)
                parent[root(parent, i)] = root(parent, it->second);
            }
      // Sectors numbered in the order of their first cell.
      std::vector<int>           sector(around.size(), -1);
      std::map<std::size_t, int> sector_of_root;
      for (std::size_t i = 0; i < around.size(); ++i)
        {
          const auto [it, inserted] =
            sector_of_root.emplace(root(parent, i), sector_of_root.size());
          sector[i] = it->second;
        }
      std::vector<long> copy_of_sector(sector_of_root.size(), v);
      for (std::size_t k = 1; k < copy_of_sector.size(); ++k)
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
     * The sides and lines after the copies: each takes the nodes of the
     * (first) cell that has it; a side on the interface becomes two, one
     * for each cell beside it, moved after the others as the sides are.
     */
    void
    relabel_sides(Msh                                           &mesh,
                  const std::vector<MshElement>                 &original,
                  const Adjacency                               &adjacency,
                  const Shapes                                  &shapes,
                  const std::function<bool(const MshElement &)> &on_interface)
    {
      const auto node_in_cell = [&](const std::size_t cell, const long v) {
        const auto &before = original[cell].nodes;
        return mesh.elements[cell]
          .nodes[std::find(before.begin(), before.end(), v) - before.begin()];
      };
      std::vector<MshElement> result, sides;
      for (std::size_t k = 0; k < original.size(); ++k)
        {
          const MshElement &e = original[k];
          if (e.type == shapes.cell || e.type == 15)
            {
              result.push_back(mesh.elements[k]);
              continue;
            }
          std::vector<MshElement> &target =
            e.type == shapes.side ? sides : result;
          const std::vector<std::size_t> beside = adjacency.cells_with(e.nodes);
          if (beside.empty())
            {
              target.push_back(e);
              continue;
            }
          for (std::size_t c = 0; c < beside.size(); ++c)
            {
              MshElement copy = e;
              for (long &v : copy.nodes)
                v = node_in_cell(beside[c], v);
              if (c > 0)
                {
                  if (!on_interface(e))
                    break;
                  copy.id = ++mesh.max_element;
                }
              target.push_back(copy);
            }
        }
      result.insert(result.end(), sides.begin(), sides.end());
      mesh.elements = result;
    }
  } // namespace


  MshFile
  split_along_curves(const MshFile &msh, const std::set<unsigned int> &curves)
  {
    if (curves.empty())
      return msh;
    const bool has_hexahedra =
      std::any_of(msh.elements.begin(),
                  msh.elements.end(),
                  [](const MshElement &e) { return e.type == 5; });
    const Shapes      &shapes    = has_hexahedra ? shapes_3d : shapes_2d;
    const std::string &mesh_file = msh.file;
    Msh                mesh      = read_msh2(msh, shapes);
    const std::vector<MshElement> original = mesh.elements;
    const Adjacency               adjacency(original, shapes);
    const auto                    on_interface = [&](const MshElement &e) {
      return e.type == shapes.side && !e.tags.empty() &&
             curves.count(static_cast<unsigned int>(e.tags[0])) != 0;
    };
    const std::set<Facet> interface =
      interface_sides(mesh, adjacency, shapes, on_interface, mesh_file);
    std::set<long> interface_nodes;
    for (const Facet &f : interface)
      interface_nodes.insert(f.begin(), f.end());
    for (const long v : interface_nodes)
      copy_node_per_sector(mesh, original, adjacency, interface, v);
    relabel_sides(mesh, original, adjacency, shapes, on_interface);
    return with_nodes_and_elements(msh, mesh);
  }
} // namespace thinlayer
